#include "core/photogrammetry/targets/target_pair.h"

#include <cmath>

#include "core/photogrammetry/camera/camera_cv.h"

namespace rockface::photogrammetry {

namespace {

Eigen::Vector2d mean_candidate_centre(const TargetObservation& t) {
  return 0.5 * (t.centre_normalised[0] + t.centre_normalised[1]);
}

}  // namespace

double target_epipolar_px(const TargetObservation& left, const TargetObservation& right,
                          const RelativeOrientation& ro, double focal_px) {
  const Eigen::Matrix3d tx =
      (Eigen::Matrix3d() << 0, -ro.t.z(), ro.t.y(), ro.t.z(), 0, -ro.t.x(), -ro.t.y(), ro.t.x(), 0)
          .finished();
  const Eigen::Matrix3d E = tx * ro.R;
  const Eigen::Vector2d na = mean_candidate_centre(left), nb = mean_candidate_centre(right);
  const Eigen::Vector3d x1(na.x(), na.y(), 1), x2(nb.x(), nb.y(), 1);
  const Eigen::Vector3d l = E * x1;
  return focal_px * std::abs(x2.dot(l)) / l.head<2>().norm();
}

int epipolar_partner(const TargetObservation& left, const std::vector<TargetObservation>& right,
                     const RelativeOrientation& ro, double focal_px, double max_px, double& err) {
  int best = -1;
  err = max_px;
  for (std::size_t j = 0; j < right.size(); ++j) {
    const double ratio = right[j].white_diameter_px / left.white_diameter_px;
    if (ratio < 0.5 || ratio > 2.0) continue;
    const double e = target_epipolar_px(left, right[j], ro, focal_px);
    const Eigen::Vector3d X = triangulate_normalised(mean_candidate_centre(left),
                                                     mean_candidate_centre(right[j]), ro.R, ro.t);
    if (X.z() <= 0 || (ro.R * X + ro.t).z() <= 0) continue;
    if (e < err) {
      err = e;
      best = static_cast<int>(j);
    }
  }
  return best;
}

TargetPair triangulate_target_pair(TargetObservation a, TargetObservation b,
                                   const CameraIntrinsics& left_camera,
                                   const CameraIntrinsics& right_camera,
                                   const RelativeOrientation& ro) {
  int ia = 0, ib = 0;
  double best = -2;
  for (int p = 0; p < 2; ++p)
    for (int q = 0; q < 2; ++q) {
      const double agree = a.normal_camera[p].dot(ro.R.transpose() * b.normal_camera[q]);
      if (agree > best) {
        best = agree;
        ia = p;
        ib = q;
      }
    }
  TargetPair out;
  out.epipolar_px = target_epipolar_px(a, b, ro, 0.5 * (left_camera.fx + right_camera.fx));
  a.centre_px = pixel_of_normalised(a.centre_normalised[ia], left_camera);
  b.centre_px = pixel_of_normalised(b.centre_normalised[ib], right_camera);
  out.model = triangulate_normalised(a.centre_normalised[ia], b.centre_normalised[ib], ro.R, ro.t);
  out.left = a;
  out.right = b;
  return out;
}

}  // namespace rockface::photogrammetry
