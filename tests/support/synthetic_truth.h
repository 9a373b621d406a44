#pragma once
// Ground-truth comparison of a reconstruction of the synthetic face
// (synthetic_face.h): facet orientations fitted on the surface, scale, tilt
// and turn about the vertical of the registered model, relative orientation
// and target centres. Shared by the integration test and the benchmark.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <opencv2/imgproc.hpp>

#include "camera/synthetic_renderer.h"
#include "core/common/units.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "tests/support/synthetic_face.h"

namespace rockface::testing {

namespace rp = photogrammetry;

struct TruthComparison {
  double worst_facet_deg = 0;  // angle between fitted and true facet normals
  double scale_error = 0;      // relative
  double north_error_deg = 0;  // rotation about the vertical
  double vertical_error_deg = 0;
  double pole_length_error_m = 0;
  double lower_target_offset_m = 0;  // the registered lower target's distance from the origin
  double rotation_error_deg = 0, direction_error_deg = 0;  // relative orientation
  double worst_target_px = 0;        // found target centre against the projected true centre
  std::size_t facet_points_min = 0;  // fewest points measured on a facet
};

inline Eigen::Vector2d pixel_of(const Eigen::Vector3d& world, const rp::CameraPose& pose,
                                const rp::CameraIntrinsics& camera) {
  return rp::project({pose.to_camera(world)}, camera)[0];
}

inline Eigen::Vector3d plane_fit_normal(const std::vector<Eigen::Vector3d>& pts) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU);
  Eigen::Vector3d n = svd.matrixU().col(2);
  return n.z() < 0 ? -n : n;
}

// Range pole and compass bearing of the reference line (magnetic, with `declination`).
inline rp::RegistrationSources pole_and_compass(const camera::SyntheticScene& scene,
                                                const camera::SyntheticRender& render,
                                                double declination) {
  const rp::CameraPose& pose = render.poses[0];
  const rp::CameraIntrinsics& cam = render.intrinsics;

  rp::RegistrationSources sources;
  sources.range_pole_m = scene.range_pole->length;
  const auto [from, to] = *scene.reference_line;
  rp::NorthReference north;
  north.from_px = pixel_of(from, pose, cam);
  north.to_px = pixel_of(to, pose, cam);
  // The compass reads magnetic north: true bearing minus the declination.
  const double true_bearing = rad_to_deg(std::atan2(to.x() - from.x(), to.y() - from.y()));
  north.azimuth_deg = true_bearing - declination;
  north.declination_deg = declination;
  sources.north = north;
  return sources;
}

// Compares a reconstruction of the synthetic face, registered by pole and
// compass, with the truth of the render.
inline TruthComparison compare_with_truth(const camera::SyntheticScene& scene,
                                          const camera::SyntheticRender& render,
                                          const rp::ReconstructionResult& result) {
  const rp::CameraPose& pose = render.poses[0];
  const rp::CameraIntrinsics& cam = render.intrinsics;
  TruthComparison out;
  out.facet_points_min = static_cast<std::size_t>(-1);
  const rp::SurfaceMesh& mesh = result.mesh;
  {
    const Eigen::Matrix3d R_true = render.poses[1].R * pose.R.transpose();
    const Eigen::Vector3d t_true =
        (render.poses[1].translation() - R_true * pose.translation()).normalized();
    out.rotation_error_deg = rp::rotation_difference_deg(result.orientation.R, R_true);
    out.direction_error_deg = rp::direction_difference_deg(result.orientation.t, t_true);
    const auto& tg = result.targets;
    for (int k = 0; k < 2 && tg; ++k)
      for (int side = 0; side < 2; ++side) {
        const Eigen::Vector2d found = side == 0 ? tg->left[k].centre_px : tg->right[k].centre_px;
        out.worst_target_px =
            std::max(out.worst_target_px, (found - render.targets[k].image[side]).norm());
      }
  }

  // The registered frame has its origin at the lower target.
  const Eigen::Vector3d origin = render.targets[0].centre;
  std::vector<Eigen::Vector3d> reco, truth;
  const Eigen::Vector2d pole_px = pixel_of(scene.range_pole->base, pose, cam);
  const auto& facets = synthetic_facets();
  for (std::size_t k = 0; k < facets.size(); ++k) {
    const auto& polygon = scene.patches[k].polygon;
    std::vector<cv::Point2f> image_polygon;
    // Sample the edges densely: with distortion they are curves in the image.
    for (std::size_t i = 0; i < polygon.size(); ++i)
      for (int s = 0; s < 20; ++s) {
        const Eigen::Vector3d p =
            polygon[i] + (polygon[(i + 1) % polygon.size()] - polygon[i]) * (s / 20.0);
        const Eigen::Vector2d px = pixel_of(p, pose, cam);
        image_polygon.emplace_back(static_cast<float>(px.x()), static_cast<float>(px.y()));
      }
    const Eigen::Vector3d n_true = facet_normal(facets[k]);
    const double offset = n_true.dot(polygon[0]);
    std::vector<Eigen::Vector3d> on_facet;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
      const cv::Point2f px(mesh.pixels[i].x(), mesh.pixels[i].y());
      // 15 px inside the facet's outline: away from its edges and the pole.
      if (cv::pointPolygonTest(image_polygon, px, true) < 15) continue;
      // Not on or right beside the pole (its targets are 35 px across).
      if (std::abs(px.x - pole_px.x()) < 40) continue;
      const Eigen::Vector3d w = mesh.vertices[i];
      on_facet.push_back(w);
      // The true surface point seen at the same left-image pixel.
      const Eigen::Vector2d ray =
          rp::undistort_to_normalised({mesh.pixels[i].cast<double>()}, cam)[0];
      const Eigen::Vector3d d = pose.R.transpose() * Eigen::Vector3d(ray.x(), ray.y(), 1.0);
      const double t = (offset - n_true.dot(pose.centre)) / n_true.dot(d);
      if (i % 7 == 0) {
        reco.push_back(w);
        truth.push_back(pose.centre + t * d - origin);
      }
    }
    out.facet_points_min = std::min(out.facet_points_min, on_facet.size());
    if (on_facet.size() < 3) continue;
    const Eigen::Vector3d n_fit = plane_fit_normal(on_facet);
    const double angle = rad_to_deg(std::acos(std::min(1.0, std::abs(n_fit.dot(n_true)))));
    out.worst_facet_deg = std::max(out.worst_facet_deg, angle);
  }

  // Similarity from the registered surface onto the truth: its scale,
  // tilt and turn about the vertical are the registration's errors.
  Eigen::Matrix3Xd A(3, reco.size()), B(3, truth.size());
  for (std::size_t i = 0; i < reco.size(); ++i) {
    A.col(i) = reco[i];
    B.col(i) = truth[i];
  }
  const Eigen::Matrix4d T = Eigen::umeyama(A, B, true);
  const double s = std::cbrt(T.topLeftCorner<3, 3>().determinant());
  const Eigen::Matrix3d R = T.topLeftCorner<3, 3>() / s;
  out.scale_error = s - 1;
  out.vertical_error_deg = rad_to_deg(std::acos(std::min(1.0, (R * Eigen::Vector3d::UnitZ()).z())));
  const Eigen::Vector3d north_dir = R * Eigen::Vector3d::UnitY();
  out.north_error_deg = rad_to_deg(std::atan2(north_dir.x(), north_dir.y()));
  if (const auto& tg = result.targets) {
    const Eigen::Vector3d lower = result.model_to_world.apply(tg->model[0]);
    const Eigen::Vector3d upper = result.model_to_world.apply(tg->model[1]);
    out.pole_length_error_m = (upper - lower).norm() - scene.range_pole->length;
    out.lower_target_offset_m = lower.norm();
  }
  std::printf(
      "relative orientation: rotation error %.4f deg (sigma %.4f), base direction %.4f deg "
      "(sigma %.4f), %d inliers, rms %.3f px\n",
      out.rotation_error_deg, result.orientation.rotation_sigma_deg, out.direction_error_deg,
      result.orientation.direction_sigma_deg, result.orientation.inliers,
      result.orientation.rms_reprojection_px);
  std::printf(
      "facets worst %.3f deg, scale error %.4f %%, north %.3f deg, vertical %.3f deg, "
      "%zu points, sigma_Z %.4f m at %.2f m, spacing %.4f m, target %.1f px\n",
      out.worst_facet_deg, 100 * out.scale_error, out.north_error_deg, out.vertical_error_deg,
      mesh.size(), result.accuracy.sigma_z, result.distance, result.point_spacing,
      result.targets ? result.targets->smallest_diameter_px : 0.0);
  return out;
}

}  // namespace rockface::testing
