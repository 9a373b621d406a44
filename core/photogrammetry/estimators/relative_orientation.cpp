#include "core/photogrammetry/estimators/relative_orientation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/photogrammetry/camera/camera_cv.h"

namespace rockface::photogrammetry {

double rotation_difference_deg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return rad_to_deg(Eigen::AngleAxisd(a.transpose() * b).angle());
}

double direction_difference_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::atan2(a.cross(b).norm(), a.dot(b)));
}

namespace {

const char* kWhere = "left/right images";

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double sampson(const Eigen::Matrix3d& E, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector3d x1(a.x(), a.y(), 1), x2(b.x(), b.y(), 1);
  const Eigen::Vector3d Ex1 = E * x1, Etx2 = E.transpose() * x2;
  const double denom = Ex1.head<2>().squaredNorm() + Etx2.head<2>().squaredNorm();
  return x2.dot(Ex1) / std::sqrt(std::max(denom, 1e-300));
}

// Five parameters around (R0, t0): a rotation vector applied on the left of
// R0 and two steps in the tangent plane of the unit base direction t0.
struct PoseParametrisation {
  Eigen::Matrix3d R0;
  Eigen::Vector3d t0, b1, b2;
  PoseParametrisation(const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
      : R0(R), t0(t.normalized()) {
    b1 = t0.unitOrthogonal();
    b2 = t0.cross(b1);
  }
  Eigen::Matrix3d rotation(const Eigen::VectorXd& x) const {
    const Eigen::Vector3d w = x.head<3>();
    const double angle = w.norm();
    if (angle < 1e-15) return R0;
    return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix() * R0;
  }
  Eigen::Vector3d translation(const Eigen::VectorXd& x) const {
    return (t0 + x(3) * b1 + x(4) * b2).normalized();
  }
};

// Sampson distances of the inliers in pixels (scaled by the mean focal length).
struct SampsonFunctor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  const PoseParametrisation* pose;
  const std::vector<Eigen::Vector2d>* a;
  const std::vector<Eigen::Vector2d>* b;
  double focal;

  int inputs() const { return 5; }
  int values() const { return static_cast<int>(a->size()); }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    const Eigen::Matrix3d E = skew(pose->translation(x)) * pose->rotation(x);
    for (std::size_t i = 0; i < a->size(); ++i) f(i) = focal * sampson(E, (*a)[i], (*b)[i]);
    return 0;
  }
};

double rms(const Eigen::VectorXd& v) {
  return v.size() ? std::sqrt(v.squaredNorm() / static_cast<double>(v.size())) : 0.0;
}

}  // namespace

void refine_relative_orientation(RelativeOrientation& ro, const std::vector<Eigen::Vector2d>& il,
                                 const std::vector<Eigen::Vector2d>& ir,
                                 const CameraIntrinsics& left, const CameraIntrinsics& right,
                                 const ReconstructionPreset& preset, Progress& progress,
                                 const OrientationLimits& limits) {
  const std::vector<Eigen::Vector2d> ia = undistort_to_normalised(il, left);
  const std::vector<Eigen::Vector2d> ib = undistort_to_normalised(ir, right);
  const double focal = 0.25 * (left.fx + left.fy + right.fx + right.fy);
  Eigen::Matrix3d R = ro.R;
  Eigen::Vector3d t = ro.t;
  ro.points.clear();
  ro.left.clear();
  ro.right.clear();
  progress.step("relative orientation: refinement", 0.0);
  PoseParametrisation param(R, t);
  SampsonFunctor functor{&param, &ia, &ib, focal};
  Eigen::VectorXd x = Eigen::VectorXd::Zero(5);
  Eigen::VectorXd f(ia.size());
  functor(x, f);
  ro.rms_sampson_before_px = rms(f);
  Eigen::NumericalDiff<SampsonFunctor> numeric(functor);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<SampsonFunctor>> lm(numeric);
  lm.parameters.maxfev = preset.refine_iterations * 6;  // 6 evaluations per Jacobian + step
  lm.parameters.xtol = 1e-12;
  lm.parameters.ftol = 1e-12;
  lm.minimize(x);
  functor(x, f);
  ro.rms_sampson_after_px = rms(f);
  if (ro.rms_sampson_after_px <= ro.rms_sampson_before_px) {
    R = param.rotation(x);
    t = param.translation(x);
  } else {
    ro.rms_sampson_after_px = ro.rms_sampson_before_px;  // keep the estimator's pose
  }
  ro.R = R;
  ro.t = t.normalized();
  {
    Eigen::MatrixXd J(ia.size(), 5);
    numeric.df(x, J);
    const double dof = std::max<double>(1.0, static_cast<double>(ia.size()) - 5.0);
    const double s2 = f.squaredNorm() / dof;
    const Eigen::MatrixXd cov =
        s2 * (J.transpose() * J).ldlt().solve(Eigen::MatrixXd::Identity(5, 5));
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> rot(cov.topLeftCorner<3, 3>());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> dir(cov.bottomRightCorner<2, 2>());
    ro.rotation_sigma_deg = rad_to_deg(std::sqrt(std::max(0.0, rot.eigenvalues().maxCoeff())));
    ro.direction_sigma_deg = rad_to_deg(std::sqrt(std::max(0.0, dir.eigenvalues().maxCoeff())));
  }

  progress.step("relative orientation: triangulation", 0.7);
  // Linear triangulation in normalised coordinates, then reprojection into
  // the distorted images for the statistics.
  cv::Matx34d P1 = cv::Matx34d::eye(), P2;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) P2(r, c) = ro.R(r, c);
    P2(r, 3) = ro.t(r);
  }
  std::vector<cv::Point2d> qa(ia.size()), qb(ib.size());
  for (std::size_t i = 0; i < ia.size(); ++i) {
    qa[i] = {ia[i].x(), ia[i].y()};
    qb[i] = {ib[i].x(), ib[i].y()};
  }
  cv::Mat X;
  cv::triangulatePoints(P1, P2, qa, qb, X);
  X.convertTo(X, CV_64F);
  std::vector<Eigen::Vector3d> pts_l, pts_r;
  std::vector<double> angles;
  const Eigen::Vector3d c2 = ro.centre_right();
  for (int i = 0; i < X.cols; ++i) {
    const double w = X.at<double>(3, i);
    if (std::abs(w) < 1e-12) continue;
    const Eigen::Vector3d p(X.at<double>(0, i) / w, X.at<double>(1, i) / w, X.at<double>(2, i) / w);
    const Eigen::Vector3d pr = ro.R * p + ro.t;
    if (p.z() <= 0 || pr.z() <= 0) continue;  // behind a camera
    pts_l.push_back(p);
    pts_r.push_back(pr);
    ro.points.push_back(p);
    ro.left.push_back(il[i]);
    ro.right.push_back(ir[i]);
    angles.push_back(direction_difference_deg(p, p - c2));
  }
  ro.inliers = static_cast<int>(ro.points.size());
  if (ro.inliers < limits.min_inliers)
    throw InputError(kWhere, "only " + std::to_string(ro.inliers) +
                                 " matched points lie in front of both cameras: the "
                                 "orientation is degenerate");
  ro.median_intersection_deg = median(angles);
  if (ro.median_intersection_deg < limits.min_intersection_deg)
    throw InputError(kWhere, "the rays intersect at only " +
                                 std::to_string(ro.median_intersection_deg) +
                                 " deg (median): the camera turned on the spot (pure rotation) or "
                                 "the base is far too short; move the camera sideways between "
                                 "the shots (base about 1/5 to 1/8 of the distance)");

  const std::vector<Eigen::Vector2d> proj_l = project(pts_l, left), proj_r = project(pts_r, right);
  std::vector<double> err;
  double sum2 = 0;
  for (std::size_t i = 0; i < proj_l.size(); ++i) {
    const double el = (proj_l[i] - ro.left[i]).norm(), er = (proj_r[i] - ro.right[i]).norm();
    err.push_back(el);
    err.push_back(er);
    sum2 += el * el + er * er;
  }
  ro.rms_reprojection_px = std::sqrt(sum2 / static_cast<double>(err.size()));
  ro.median_reprojection_px = median(err);

  std::vector<cv::Point2f> hull_in, hull;
  for (const auto& p : ro.left)
    hull_in.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  cv::convexHull(hull_in, hull);
  const double area = static_cast<double>(left.width) * left.height;
  ro.overlap_fraction = area > 0 ? cv::contourArea(hull) / area : 0.0;
  progress.step("relative orientation: refinement", 1.0);
}

RelativeOrientation estimate_relative_orientation(
    const FeatureMatches& matches, const CameraIntrinsics& left, const CameraIntrinsics& right,
    const ReconstructionPreset& preset, Progress& progress, const OrientationLimits& limits) {
  RelativeOrientation ro;
  ro.matches = static_cast<int>(matches.size());
  if (matches.keypoints_left < limits.min_matches)
    throw InputError("left image",
                     "only " + std::to_string(matches.keypoints_left) +
                         " features found: the image is blank, black or out of focus");
  if (matches.keypoints_right < limits.min_matches)
    throw InputError("right image",
                     "only " + std::to_string(matches.keypoints_right) +
                         " features found: the image is blank, black or out of focus");
  if (ro.matches < limits.min_matches)
    throw InputError(kWhere, "only " + std::to_string(ro.matches) +
                                 " feature matches between the images (need " +
                                 std::to_string(limits.min_matches) +
                                 "): they do not overlap or show different scenes");

  // Identical images (or a camera that did not move): no parallax at all.
  std::vector<double> motion(matches.size());
  for (std::size_t i = 0; i < matches.size(); ++i)
    motion[i] = (matches.left[i] - matches.right[i]).norm();
  const double median_motion = median(motion);
  if (median_motion < limits.min_parallax_px)
    throw InputError(kWhere, "the two images are identical (median image motion " +
                                 std::to_string(median_motion) +
                                 " px): take the second photograph from another station");

  progress.step("relative orientation: essential matrix", 0.0);
  const std::vector<Eigen::Vector2d> a = undistort_to_normalised(matches.left, left);
  const std::vector<Eigen::Vector2d> b = undistort_to_normalised(matches.right, right);
  std::vector<cv::Point2d> pa(a.size()), pb(b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    pa[i] = {a[i].x(), a[i].y()};
    pb[i] = {b[i].x(), b[i].y()};
  }
  const double focal = 0.25 * (left.fx + left.fy + right.fx + right.fy);
  const double threshold = preset.ransac_threshold_px / focal;  // normalised units
  cv::Mat mask;
  const cv::Mat E = cv::findEssentialMat(pa, pb, cv::Matx33d::eye(), cv::USAC_MAGSAC, 0.9999,
                                         threshold, 10000, mask);
  if (E.rows != 3 || E.cols != 3)
    throw InputError(kWhere,
                     "no essential matrix fits the matches: the images do not overlap "
                     "or show a moving scene");

  progress.step("relative orientation: pose", 0.3);
  cv::Mat Rcv, tcv;
  // Points farther than this many base lengths are at infinity for cheirality.
  const double far = 1000.0;
  cv::Mat triangulated;
  cv::recoverPose(E, pa, pb, cv::Matx33d::eye(), Rcv, tcv, far, mask, triangulated);
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  cv::cv2eigen(Rcv, R);
  cv::cv2eigen(tcv, t);

  std::vector<Eigen::Vector2d> ia, ib, il, ir;
  for (int i = 0; i < mask.rows; ++i)
    if (mask.at<uchar>(i)) {
      ia.push_back(a[i]);
      ib.push_back(b[i]);
      il.push_back(matches.left[i]);
      ir.push_back(matches.right[i]);
    }
  if (static_cast<int>(ia.size()) < limits.min_inliers)
    throw InputError(kWhere, "only " + std::to_string(ia.size()) + " of " +
                                 std::to_string(ro.matches) +
                                 " matches agree on one relative orientation (need " +
                                 std::to_string(limits.min_inliers) +
                                 "): too little overlap, or repetitive texture");

  ro.R = R;
  ro.t = t.normalized();
  refine_relative_orientation(ro, il, ir, left, right, preset, progress, limits);
  progress.step("relative orientation", 1.0);
  return ro;
}

}  // namespace rockface::photogrammetry
