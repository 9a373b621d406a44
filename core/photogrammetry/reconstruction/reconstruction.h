#pragma once
// Two-view reconstruction end to end: features -> relative orientation ->
// rectification and dense matching -> lattice surface ("3D image") ->
// registration (range pole, north, control points, base) -> accuracy.
// The composition only; each step lives in its own file.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/estimators/registration.h"
#include "core/photogrammetry/estimators/relative_orientation.h"
#include "core/photogrammetry/matching/dense_matching.h"
#include "core/photogrammetry/matching/tie_point_refinement.h"
#include "core/photogrammetry/matching/view_shading.h"
#include "core/photogrammetry/reconstruction/accuracy.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/surface/surface_mesh.h"
#include "core/photogrammetry/targets/circular_target.h"

namespace rockface::photogrammetry {

// The compass bearing of a reference line given by two pixels of the left image.
struct NorthReference {
  Eigen::Vector2d from_px, to_px;
  double azimuth_deg = 0;      // compass bearing from `from` to `to`, clockwise from north
  double declination_deg = 0;  // magnetic declination, east positive
  // How a refusal names it: the command line's option, or the scene's
  // field when a replay takes it from a scene.
  std::string where = "--reference-line";
};

struct RegistrationSources {
  std::optional<double> range_pole_m;  // distance between the two target centres
  std::optional<NorthReference> north;
  std::vector<ControlPoint> control_points;  // three or more, or none
  std::string control_points_where = "--gcp";
  std::optional<double> baseline_m;  // distance between the camera stations
};

// A scale source that was given but not used, checked against the one used.
struct ScaleCheck {
  std::string source;
  double ratio = 1;  // its scale / the scale used
};

struct ReconstructionResult {
  SurfaceMesh mesh;  // scene frame, datum-relative (add `datum` for absolute coordinates)
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  RelativeOrientation orientation;
  TiePointRefinementStats tie_points;  // area matching of the tie points
  Similarity model_to_world;
  bool scaled = false;
  std::string scale_source = "none";  // "range pole" | "control points" | "baseline" | "none"
  std::string vertical_source = "levelled camera";  // or "range pole" | "control points"
  std::string north_source = "none";                // "compass" | "control points" | "none"
  std::optional<RangePoleTargets> targets;
  std::optional<ControlPointRegistration> control_points;
  std::optional<double> north_rotation_deg;  // applied about the vertical
  std::vector<ScaleCheck> scale_checks;

  DisparityRange disparity_range;
  double dense_scale = 0;
  // How the two views' brightness of the same rock differs (view_shading.h),
  // and whether dense matching ran on brightness-normalised images for it.
  ViewShading view_shading;
  bool shading_normalised = false;
  double dense_valid_fraction = 0;
  double lr_rejected_fraction = 0;
  double distance = 0;            // median depth, world units
  double base = 0;                // world units
  double point_spacing = 0;       // median lattice edge, world units
  double focal_px = 0;            // of the rectified images (dense scale)
  double disparity_sigma_px = 0;  // assumed disparity precision at that scale
  AccuracyPrediction accuracy;
};

ReconstructionResult reconstruct(const cv::Mat& left_image, const cv::Mat& right_image,
                                 const CameraIntrinsics& left, const CameraIntrinsics& right,
                                 const ReconstructionPreset& preset,
                                 const RegistrationSources& sources, Progress& progress);

}  // namespace rockface::photogrammetry
