#pragma once
// Relative orientation of two calibrated views: essential matrix with
// MAGSAC++ (OpenCV USAC), pose recovery (cheirality), then a Levenberg-
// Marquardt refinement of the five degrees of freedom (rotation, direction of
// the base) over the inliers, minimising the Sampson distance. The model frame
// is the left camera's, with the base |t| = 1.
#include <vector>

#include <Eigen/Core>

#include "core/common/progress.h"
#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/reconstruction/preset.h"

namespace rockface::photogrammetry {

struct RelativeOrientation {
  // x_right = R x_left + t, |t| = 1 (the model unit is the base).
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::UnitX();

  int matches = 0;                           // after ratio test and mutual check
  int inliers = 0;                           // of the essential matrix and in front of both cameras
  std::vector<Eigen::Vector2d> left, right;  // inlier pixels (original, distorted)
  std::vector<Eigen::Vector3d> points;       // the inliers triangulated, left camera frame

  double rms_reprojection_px = 0;  // both images, after refinement
  double median_reprojection_px = 0;
  double rms_sampson_before_px = 0;  // before the refinement (shows what it gained)
  double rms_sampson_after_px = 0;
  // One standard deviation of the refined orientation, from the Jacobian of
  // the Sampson residuals scaled by their RMS (largest axis of the error ellipsoid).
  double rotation_sigma_deg = 0;
  double direction_sigma_deg = 0;
  double median_intersection_deg = 0;  // angle between the two rays at the points
  double overlap_fraction = 0;         // convex hull of the inliers / left image area
  Eigen::Vector3d centre_right() const { return -R.transpose() * t; }
};

// Thresholds below which the pair cannot be oriented; exposed so that the
// warnings of the report use the same numbers.
struct OrientationLimits {
  int min_matches = 30;  // fewer: the images do not show the same scene
  int min_inliers = 20;
  double min_parallax_px = 1.0;       // median image motion; below: identical images
  double min_intersection_deg = 1.0;  // below: pure rotation or a base far too short
};

// Throws InputError("left/right images", ...) when the pair cannot be
// oriented: identical images, no overlap, pure rotation, blank images.
RelativeOrientation estimate_relative_orientation(
    const FeatureMatches& matches, const CameraIntrinsics& left, const CameraIntrinsics& right,
    const ReconstructionPreset& preset, Progress& progress, const OrientationLimits& limits = {});

// Levenberg-Marquardt refinement of ro.R, ro.t over the tie points (pixels,
// original images), then triangulation and the statistics of `ro`. Used by
// estimate_relative_orientation and again after the tie points have been
// re-located by area matching (tie_point_refinement.h).
void refine_relative_orientation(RelativeOrientation& ro,
                                 const std::vector<Eigen::Vector2d>& left_px,
                                 const std::vector<Eigen::Vector2d>& right_px,
                                 const CameraIntrinsics& left, const CameraIntrinsics& right,
                                 const ReconstructionPreset& preset, Progress& progress,
                                 const OrientationLimits& limits = {});

// Angle of the rotation R_a^T R_b, degrees; angle between two directions, degrees.
double rotation_difference_deg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);
double direction_difference_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace rockface::photogrammetry
