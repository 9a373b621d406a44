#include "core/photogrammetry/reconstruction/reconstruction.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "core/photogrammetry/estimators/triangulation.h"
#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/matching/image_contrast.h"
#include "core/photogrammetry/matching/tie_point_refinement.h"
#include "core/photogrammetry/matching/view_shading.h"
#include "core/photogrammetry/surface/surface_pick.h"
#include "core/photogrammetry/targets/control_targets.h"

namespace rockface::photogrammetry {

namespace {

// Maps the overall fractions of the stages onto one progress bar.
class StageProgress final : public Progress {
 public:
  StageProgress(Progress& outer, double begin, double end)
      : outer_(outer), begin_(begin), end_(end) {}
  void report(std::string_view stage, double f) override {
    outer_.report(stage, begin_ + (end_ - begin_) * std::clamp(f, 0.0, 1.0));
  }
  bool cancel_requested() const override { return outer_.cancel_requested(); }

 private:
  Progress& outer_;
  double begin_, end_;
};

cv::Mat resized(const cv::Mat& image, double scale) {
  if (scale == 1.0) return image;
  cv::Mat out;
  cv::resize(image, out, cv::Size(), scale, scale, cv::INTER_AREA);
  return out;
}

Eigen::Vector3d surface_at(const SurfaceMesh& mesh, const Eigen::Vector2d& px, double radius,
                           const std::string& where) {
  const auto p = mesh.point_at_pixel(px, radius);
  if (!p)
    throw InputError(where, "no reconstructed surface at pixel (" + std::to_string(px.x()) + ", " +
                                std::to_string(px.y()) + ") of the left image");
  return *p;
}

// The compass line's ends: its bearing turns the whole model about the
// pole, so each end is read from the plane around it, not one vertex
// (surface_pick.h).
Eigen::Vector3d surface_at_pick(const SurfaceMesh& mesh, const Eigen::Vector2d& px,
                                const CameraIntrinsics& left, const std::string& where) {
  const auto p = surface_point_at_pick(mesh, px, left);
  if (!p)
    throw InputError(where, "no reconstructed surface at pixel (" + std::to_string(px.x()) + ", " +
                                std::to_string(px.y()) + ") of the left image");
  return *p;
}

double median_depth(const SurfaceMesh& mesh) {
  std::vector<double> z;
  const std::size_t stride = std::max<std::size_t>(1, mesh.size() / 50000);
  for (std::size_t i = 0; i < mesh.size(); i += stride) z.push_back(mesh.vertices[i].z());
  if (z.empty()) return 0;
  auto mid = z.begin() + z.size() / 2;
  std::nth_element(z.begin(), mid, z.end());
  return *mid;
}

}  // namespace

ReconstructionResult reconstruct(const cv::Mat& left_image, const cv::Mat& right_image,
                                 const CameraIntrinsics& left, const CameraIntrinsics& right,
                                 const ReconstructionPreset& preset,
                                 const RegistrationSources& sources, Progress& progress) {
  check_camera_fits_image(left, left_image, "left image");
  check_camera_fits_image(right, right_image, "right image");
  // Haze, darkness or noise: refused by name before matching blames the overlap.
  require_matchable_contrast(left_image, "left image");
  require_matchable_contrast(right_image, "right image");
  ReconstructionResult out;

  {
    StageProgress p(progress, 0.0, 0.25);
    const FeatureMatches matches = match_features(left_image, right_image, preset, p);
    StageProgress q(progress, 0.25, 0.3);
    out.orientation = estimate_relative_orientation(matches, left, right, preset, q);
    // Area matching removes the foreshortening bias of the SIFT positions;
    // the orientation is then refined again over the re-located tie points.
    StageProgress r(progress, 0.3, 0.35);
    std::vector<Eigen::Vector2d> tl = out.orientation.left, tr = out.orientation.right;
    TiePointRefinementOptions lsm;
    lsm.half_window_px = std::max(
        lsm.half_window_px,
        static_cast<int>(std::lround(lsm.half_window_px /
                                     working_scale(left_image.cols, preset.feature_max_width))) /
            2);
    out.tie_points = refine_tie_points(to_grey(left_image), to_grey(right_image), tl, tr, lsm, r);
    if (static_cast<int>(tl.size()) >= OrientationLimits{}.min_inliers)
      refine_relative_orientation(out.orientation, tl, tr, left, right, preset, r);
  }
  const RelativeOrientation& ro = out.orientation;

  // Dense matching at the preset's scale; the full-size images are only read.
  out.dense_scale = working_scale(left_image.cols, preset.dense_max_width);
  const Rectification rect = rectify(left, right, ro, out.dense_scale);
  out.disparity_range = disparity_range_from_inliers(ro, rect, left, right, preset);
  cv::Mat rect_left, rect_right;
  {
    progress.step("rectification", 0.36);
    const cv::Mat small_left = resized(left_image, out.dense_scale);
    cv::remap(small_left, rect_left, rect.map1x, rect.map1y, cv::INTER_LINEAR);
  }
  {
    const cv::Mat small_right = resized(right_image, out.dense_scale);
    cv::remap(small_right, rect_right, rect.map2x, rect.map2y, cv::INTER_LINEAR);
  }
  // A flash on the camera lights each view from its own station; dense
  // matching would follow the shading (view_shading.h). Then both views are
  // matched divided by their local brightness; rect_left keeps the colours.
  {
    const RectifiedTiePoints q = rectified_tie_points(ro, rect, left, right);
    out.view_shading = compare_view_shading(rect_left, rect_right, q.left, q.right);
  }
  out.shading_normalised = shading_differs(out.view_shading);
  DisparityMap disparity;
  {
    StageProgress p(progress, 0.4, 0.85);
    if (out.shading_normalised)
      disparity =
          match_rectified(normalise_local_brightness(rect_left, kShadingNormalisationSigmaPx),
                          normalise_local_brightness(rect_right, kShadingNormalisationSigmaPx),
                          out.disparity_range, preset, p, rect_left);
    else
      disparity = match_rectified(rect_left, rect_right, out.disparity_range, preset, p);
  }
  rect_right.release();
  out.dense_valid_fraction = disparity.valid_fraction;
  out.lr_rejected_fraction = disparity.lr_rejected_fraction;
  {
    StageProgress p(progress, 0.85, 0.95);
    LatticeOptions lattice;
    lattice.step = preset.lattice_step;
    out.mesh = triangulate_lattice(disparity, rect, rect_left, left, lattice, p);
  }
  if (out.mesh.size() < 100)
    throw InputError("left/right images",
                     "dense matching found almost no surface (" + std::to_string(out.mesh.size()) +
                         " points): the images are blank, blurred or do not overlap");
  progress.step("registration", 0.95);

  // Registration. The model frame is the left camera's, base 1.
  // Pixels of lattice vertices are about 1/dense_scale * step full-size px apart.
  const double pick_radius = 2.0 * preset.lattice_step / out.dense_scale;
  Similarity T;  // model -> world
  std::optional<double> scale_pole, scale_base;
  if (sources.range_pole_m) {
    out.targets = find_range_pole(left_image, right_image, left, right, ro);
    const Similarity pole = range_pole_registration(out.targets->model[0], out.targets->model[1],
                                                    *sources.range_pole_m);
    scale_pole = pole.scale;
  }
  if (sources.baseline_m) scale_base = baseline_scale(*sources.baseline_m).scale;

  if (!sources.control_points.empty()) {
    std::vector<Eigen::Vector2d> picks;
    for (const auto& cp : sources.control_points) picks.push_back(cp.pixel);
    const auto on_targets =
        measure_control_targets(left_image, right_image, left, right, ro, picks);
    std::vector<Eigen::Vector3d> model;
    for (std::size_t k = 0; k < picks.size(); ++k) {
      const auto& cp = sources.control_points[k];
      model.push_back(on_targets[k] ? on_targets[k]->model
                                    : surface_at(out.mesh, cp.pixel, pick_radius,
                                                 sources.control_points_where + " point " + cp.id));
    }
    out.control_points =
        register_to_control_points(model, sources.control_points, sources.control_points_where);
    for (std::size_t k = 0; k < out.control_points->residuals.size(); ++k)
      out.control_points->residuals[k].on_target = on_targets[k].has_value();
    T = out.control_points->transform;
    out.datum = out.control_points->datum;
    out.scaled = true;
    out.scale_source = out.vertical_source = out.north_source = "control points";
  } else {
    if (out.targets) {
      T = range_pole_registration(out.targets->model[0], out.targets->model[1],
                                  *sources.range_pole_m);
      out.scale_source = out.vertical_source = "range pole";
      out.scaled = true;
    } else {
      T = levelled_camera_frame();
      if (scale_base) {
        T.scale = *scale_base;
        out.scale_source = "baseline";
        out.scaled = true;
      }
    }
    if (sources.north) {
      const std::string& where = sources.north->where;
      const Eigen::Vector3d a =
          T.apply(surface_at_pick(out.mesh, sources.north->from_px, left, where + " first point"));
      const Eigen::Vector3d b =
          T.apply(surface_at_pick(out.mesh, sources.north->to_px, left, where + " second point"));
      // About the vertical through the frame's origin (the lower target, or
      // the left camera without a pole), so the origin stays where
      // registration.h says it is.
      const Similarity north = [&] {
        try {
          return north_rotation(a, b, sources.north->azimuth_deg, sources.north->declination_deg);
        } catch (const InputError& e) {
          throw InputError(where, e.reason());  // the line as the user gave it
        }
      }();
      out.north_rotation_deg = rad_to_deg(Eigen::AngleAxisd(north.R).angle()) *
                               (Eigen::AngleAxisd(north.R).axis().z() < 0 ? -1 : 1);
      T = T.then(north);
      out.north_source = "compass";
    }
  }
  // Scale sources given but not used become checks of the one used.
  if (out.scale_source != "range pole" && scale_pole)
    out.scale_checks.push_back({"range pole", *scale_pole / T.scale});
  if (out.scale_source != "baseline" && scale_base)
    out.scale_checks.push_back({"baseline", *scale_base / T.scale});

  const double distance_model = median_depth(out.mesh);
  out.mesh.transform(T.scale, T.R, T.t);
  out.model_to_world = T;
  out.distance = distance_model * T.scale;
  out.base = T.scale;  // the model base is 1
  out.point_spacing = out.mesh.median_edge_length();

  out.focal_px = rect.focal_px();
  out.disparity_sigma_px = preset.disparity_sigma_px;
  AccuracyInputs acc;
  acc.distance = out.distance;
  acc.base = out.base;
  acc.focal_px = rect.focal_px();
  acc.disparity_sigma_px = preset.disparity_sigma_px;
  acc.inliers = ro.inliers;
  acc.overlap = out.dense_valid_fraction;
  if (out.targets) acc.smallest_target_px = out.targets->smallest_diameter_px;
  out.accuracy = predict_accuracy(acc);
  if (out.shading_normalised) out.accuracy.warnings.push_back(shading_warning(out.view_shading));
  if (!out.scaled)
    out.accuracy.warnings.push_back("no scale source given: the model is in units of the base");
  if (out.vertical_source == "levelled camera")
    out.accuracy.warnings.push_back(
        "no vertical source (range pole or control points): up is the left camera's up, good "
        "only as far as the camera was levelled");
  if (out.north_source == "none")
    out.accuracy.warnings.push_back(
        "no north source (--azimuth with --reference-line, or control points): +y is the left "
        "camera's viewing direction, not north");
  for (const auto& c : out.scale_checks)
    if (std::abs(c.ratio - 1) > 0.01)
      out.accuracy.warnings.push_back("the " + c.source + " disagrees with the " +
                                      out.scale_source + " scale by " +
                                      std::to_string(100 * (c.ratio - 1)) + " %");
  progress.step("done", 1.0);
  return out;
}

}  // namespace rockface::photogrammetry
