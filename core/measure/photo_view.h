#pragma once
// The photographs a measurement is made on: a calibrated camera with its
// pose in the frame of the 3D image, the ray through one of its pixels, and
// the record of where a measurement came from (photo and pixel), so that it
// can be shown again and stored.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/estimators/registration.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

// A pixel of a named photograph ("left", "right", or the name of a rendered
// view of the 3D image). Pixel coordinates follow OpenCV (SCENE.md).
struct PhotoPixel {
  std::string photo;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

struct PhotoView {
  std::string name;  // "left", "right", ...
  photogrammetry::CameraIntrinsics camera;
  photogrammetry::CameraPose pose;  // world-to-camera in the mesh's frame
};

// A half-line: origin and unit direction.
struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

// True when the pixel lies on the image (within half a pixel of the border
// pixels' centres) and is finite.
bool pixel_in_image(const PhotoView& view, const Eigen::Vector2d& pixel);

// The ray of a (distorted) pixel. Throws InputError(where, ...) for a pixel
// that is not finite or lies outside the image.
Ray ray_through_pixel(const PhotoView& view, const Eigen::Vector2d& pixel,
                      const std::string& where);

// Pixels of world points in the view (distortion included); points behind
// the camera get NaN.
std::vector<Eigen::Vector2d> project_to_view(const PhotoView& view,
                                             const std::vector<Eigen::Vector3d>& points);

// The views of a registered two-view model. The model frame is the left
// camera's (core/photogrammetry/estimators/relative_orientation.h) and model_to_world
// maps it onto the mesh's frame; the right camera sits at R_rel, t_rel from
// the left (x_right = R_rel x_left + t_rel). A stored project keeps
// model_to_world as its registration.
PhotoView left_view(const photogrammetry::Similarity& model_to_world,
                    const photogrammetry::CameraIntrinsics& left);
PhotoView right_view(const photogrammetry::Similarity& model_to_world, const Eigen::Matrix3d& R_rel,
                     const Eigen::Vector3d& t_rel, const photogrammetry::CameraIntrinsics& right);

// The left view recovered from the 3D image alone: every lattice vertex
// knows its pixel in the left photograph, so the pose follows from those
// 2D-3D pairs (cv::solvePnP on a sample). For a model read back from a PLY
// file, where no pose is stored. Throws InputError("mesh", ...) when the mesh
// has no pixels or too few vertices.
PhotoView left_view_from_lattice(const photogrammetry::SurfaceMesh& mesh,
                                 const photogrammetry::CameraIntrinsics& left);

}  // namespace rockface::measure
