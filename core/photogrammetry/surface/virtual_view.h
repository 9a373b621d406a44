#pragma once
// A photograph of a 3D image that no camera took: an imported scan or mesh
// drawn by a pinhole camera looking squarely at its best plane, so that the
// geologist maps on it (traces, areas, Find traces) exactly as on a
// photographed face: every vertex has its pixel in the view (its texture
// coordinate), and a tap in the view is a point of the surface.
//
// The pixel is about the point spacing, so that a tap finds a vertex within a
// pixel or two where the surface is measured, and nothing across a hole (a
// hole is drawn in the background grey). Colour comes from the texture where
// the mesh has one, else from the vertex colours, else grey shaded by the
// surface's slope to the view (a scan without colour still shows its relief).
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::photogrammetry {

struct VirtualViewInput {
  const std::vector<Eigen::Vector3d>* vertices = nullptr;
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<std::array<std::uint8_t, 3>>* colours = nullptr;  // RGB; may be empty
  const std::vector<std::array<float, 2>>* texcoords =
      nullptr;      // (u, v down) in [0, 1]; may be empty
  cv::Mat texture;  // BGR, what the texcoords refer to; may be empty
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();          // of the surface
  Eigen::Vector3d toward_viewer = Eigen::Vector3d::UnitZ();  // unit: from the surface to the camera
  double point_spacing = 0;                                  // median, metres; sets the pixel size
};

struct VirtualViewOptions {
  int max_side_px = 4096;  // a 16 Mpx view at most (48 MB of pixels)
  int min_side_px = 256;
  // The camera stands this many surface extents away: a gentle perspective
  // (the view's scale changes by about the relief over this distance).
  double distance_to_extent = 2.0;
};

struct VirtualView {
  CameraIntrinsics intrinsics;  // a pinhole without distortion
  CameraPose pose;              // world to camera (x right, y down, z forward)
  cv::Mat image;                // BGR
  // Each vertex's pixel in the view, and its texture coordinate in it
  // (u, v down, in [0, 1]).
  std::vector<Eigen::Vector2f> pixels;
  std::vector<std::array<float, 2>> texcoords;
};

VirtualView render_virtual_view(const VirtualViewInput& input,
                                const VirtualViewOptions& options = {});

}  // namespace rockface::photogrammetry
