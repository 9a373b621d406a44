#pragma once
// Circular targets of the range pole: a white disk inside a black ring. The
// ring's width differs between makers (outer diameter 1.3 to 3 times the
// disk's and more; camera/synthetic_renderer.h draws 2); it is not assumed
// but measured along rays, and the ring may merge into dark rock around it.
// Detection is by contours of the white disk at several thresholds, checked
// for a dark surrounding ring; the edge is then located to sub-pixel
// precision along rays from the centre (mid-level crossing, levels per ray,
// so a shadow across the target does not shift it), the edge points are
// undistorted and an ellipse is fitted to them.
//
// Under perspective the centre of the imaged ellipse is not the image of the
// circle's centre. The ellipse (a cone through the camera centre) admits two
// circle-plane normals; for each, the image of the centre is Q^-1 n (the pole
// of the plane's vanishing line). The normal is chosen by agreement between
// the two views.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/estimators/relative_orientation.h"

namespace rockface::photogrammetry {

struct TargetObservation {
  Eigen::Vector2d ellipse_centre;  // pixels (distorted image), centre of the fitted ellipse
  // Undistorted, normalised image coordinates of the circle's centre for the
  // two possible plane normals (equal for a face-on target).
  std::array<Eigen::Vector2d, 2> centre_normalised;
  std::array<Eigen::Vector3d, 2> normal_camera;  // unit, toward the camera
  Eigen::Vector2d centre_px;     // the chosen corrected centre, pixels (distorted image)
  double white_diameter_px = 0;  // the white disk across, major axis (ideal pixels)
  double ring_ratio = 0;   // the ring's outer diameter / the disk's; 0 where not seen (dark rock)
  double diameter_px = 0;  // the target across: white disk x ring ratio where seen, major axis
  double contrast = 0;     // white minus black grey level
  double white_level = 0;  // grey level of the white disk (median over rays)
  double fit_rms_px = 0;   // sub-pixel edge points against the ellipse
};

struct TargetDetectorOptions {
  double min_white_diameter_px = 3.0;         // below: not resolvable
  double max_white_diameter_fraction = 0.25;  // of the image height
  double min_contrast = 40;                   // grey levels between the white and black disks
  double max_black_to_white = 0.4;  // grey level of the black ring / the white disk, per ray
  double max_axis_ratio = 4.0;      // more oblique than 75 deg: not a usable target
  double max_fit_rms_px = 0.6;      // edge points against the ellipse
  double max_edge_width_px =
      3.2;  // 75 % -> 25 % of the contrast across the edge: a 2 px (sigma) blur
};

// All targets in one image (8-bit grey or BGR), best contrast first.
std::vector<TargetObservation> detect_targets(const cv::Mat& image, const CameraIntrinsics& camera,
                                              const TargetDetectorOptions& options = {});
// The same with thresholds down into the shadows (a target in a tunnel lit
// by lamps or a flash, its white below the usual thresholds): tried when the
// usual ones miss a target.
std::vector<TargetObservation> detect_targets_in_the_dark(
    const cv::Mat& image, const CameraIntrinsics& camera,
    const TargetDetectorOptions& options = {});

struct RangePoleTargets {
  // [0] lower, [1] upper target; left and right observations.
  std::array<TargetObservation, 2> left, right;
  std::array<Eigen::Vector3d, 2> model;  // triangulated centres, model frame (left camera, base 1)
  double smallest_diameter_px = 0;       // of the four observations
};

// Finds the two targets of a vertical range pole in both images: a pair in
// the left image one above the other, each with an epipolar partner in the
// right image. The lower target is the one lower in the image (nearer the
// ground; stations have no roll). Corrects the ellipse-centre bias and
// triangulates. Throws InputError("range pole", ...) naming where it looked.
RangePoleTargets find_range_pole(const cv::Mat& left_image, const cv::Mat& right_image,
                                 const CameraIntrinsics& left, const CameraIntrinsics& right,
                                 const RelativeOrientation& ro,
                                 const TargetDetectorOptions& options = {});

// The two candidate normals of a circle whose image is the conic Q in
// normalised coordinates (x^T Q x = 0), and the image of its centre for each.
// Exposed for tests.
struct CircleFromConic {
  std::array<Eigen::Vector3d, 2> normal;  // unit, toward the camera (n.z < 0)
  std::array<Eigen::Vector2d, 2> centre;  // normalised image coordinates
};
CircleFromConic circle_from_conic(const Eigen::Matrix3d& Q);

// Conic matrix (x^T C x = 0) of an ellipse given by centre, full axes and
// angle in degrees (cv::RotatedRect convention).
Eigen::Matrix3d ellipse_conic(const cv::RotatedRect& ellipse);

// Linear triangulation of one correspondence in normalised coordinates;
// the point in the left camera frame.
Eigen::Vector3d triangulate_normalised(const Eigen::Vector2d& left, const Eigen::Vector2d& right,
                                       const Eigen::Matrix3d& R, const Eigen::Vector3d& t);

}  // namespace rockface::photogrammetry
