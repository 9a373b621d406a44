#include "core/photogrammetry/matching/tie_point_refinement.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace rockface::photogrammetry {

namespace {

// The affine map left -> right fitted to the nearest tie points (least squares).
Eigen::Matrix<double, 2, 3> local_affine(std::size_t i, const std::vector<Eigen::Vector2d>& left,
                                         const std::vector<Eigen::Vector2d>& right, int k) {
  std::vector<std::pair<double, std::size_t>> near;
  near.reserve(left.size());
  for (std::size_t j = 0; j < left.size(); ++j)
    near.emplace_back((left[j] - left[i]).squaredNorm(), j);
  const std::size_t n = std::min<std::size_t>(near.size(), static_cast<std::size_t>(k));
  std::partial_sort(near.begin(), near.begin() + n, near.end());
  Eigen::Matrix<double, 2, 3> A;
  A << 1, 0, right[i].x() - left[i].x(), 0, 1, right[i].y() - left[i].y();
  if (n < 6) return A;
  Eigen::MatrixXd M(n, 3);
  Eigen::MatrixXd Y(n, 2);
  for (std::size_t r = 0; r < n; ++r) {
    const std::size_t j = near[r].second;
    M.row(r) << left[j].x() - left[i].x(), left[j].y() - left[i].y(), 1;
    Y.row(r) = right[j].transpose();
  }
  const Eigen::MatrixXd X = M.colPivHouseholderQr().solve(Y);  // 3 x 2
  const Eigen::Matrix2d L = X.topRows<2>().transpose();
  // A neighbourhood across an occlusion edge gives a wild map: keep identity then.
  if (!(L.determinant() > 0.3 && L.determinant() < 3.0)) return A;
  A.leftCols<2>() = L;
  A.col(2) = right[i] - L * left[i];  // anchored on this pair's own SIFT match
  return A;
}

}  // namespace

TiePointRefinementStats refine_tie_points(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                          std::vector<Eigen::Vector2d>& left,
                                          std::vector<Eigen::Vector2d>& right,
                                          const TiePointRefinementOptions& o, Progress& progress) {
  TiePointRefinementStats stats;
  const int h = o.half_window_px, size = 2 * h + 1;
  std::vector<Eigen::Vector2d> kept_left, kept_right;
  std::vector<double> shifts;
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 1e-4);
  for (std::size_t i = 0; i < left.size(); ++i) {
    if (i % 256 == 0)
      progress.step("tie points: area matching", static_cast<double>(i) / left.size());
    const Eigen::Matrix<double, 2, 3> A = local_affine(i, left, right, o.neighbours);
    // Template: the window centred exactly on the left point (bilinear).
    cv::Mat templ;
    cv::getRectSubPix(left_grey, cv::Size(size, size),
                      cv::Point2f(static_cast<float>(left[i].x()), static_cast<float>(left[i].y())),
                      templ, CV_32F);
    // Search region of the right image around the predicted window.
    const int margin = h * 2 + 8;
    const cv::Rect region = cv::Rect(static_cast<int>(std::floor(right[i].x())) - margin,
                                     static_cast<int>(std::floor(right[i].y())) - margin,
                                     2 * margin + 1, 2 * margin + 1) &
                            cv::Rect(0, 0, right_grey.cols, right_grey.rows);
    if (region.width < 2 * margin + 1 || region.height < 2 * margin + 1) {
      ++stats.rejected;  // too near the border for a full window
      continue;
    }
    cv::Mat input;
    right_grey(region).convertTo(input, CV_32F);
    // Template pixel x_t maps to right pixel A (left + x_t - h) + b, in
    // region coordinates minus the region's origin.
    const Eigen::Vector2d shift0 = A.leftCols<2>() * (left[i] - Eigen::Vector2d(h, h)) + A.col(2) -
                                   Eigen::Vector2d(region.x, region.y);
    cv::Mat warp =
        (cv::Mat_<float>(2, 3) << A(0, 0), A(0, 1), shift0.x(), A(1, 0), A(1, 1), shift0.y());
    double rho = 0;
    try {
      rho = cv::findTransformECC(templ, input, warp, cv::MOTION_AFFINE, criteria, cv::noArray(), 1);
    } catch (const cv::Exception&) {
      ++stats.rejected;  // did not converge
      continue;
    }
    const Eigen::Vector2d refined(
        warp.at<float>(0, 0) * h + warp.at<float>(0, 1) * h + warp.at<float>(0, 2) + region.x,
        warp.at<float>(1, 0) * h + warp.at<float>(1, 1) * h + warp.at<float>(1, 2) + region.y);
    const double moved = (refined - right[i]).norm();
    if (rho < o.min_correlation || moved > o.max_shift_px) {
      ++stats.rejected;
      continue;
    }
    shifts.push_back(moved);
    kept_left.push_back(left[i]);
    kept_right.push_back(refined);
  }
  stats.refined = static_cast<int>(kept_left.size());
  if (!shifts.empty()) {
    auto mid = shifts.begin() + shifts.size() / 2;
    std::nth_element(shifts.begin(), mid, shifts.end());
    stats.median_shift_px = *mid;
  }
  left.swap(kept_left);
  right.swap(kept_right);
  return stats;
}

}  // namespace rockface::photogrammetry
