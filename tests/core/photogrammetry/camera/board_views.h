#pragma once
// Synthetic views of a chessboard through a known camera (pinhole + Brown
// distortion), for calibration tests. The board is box-filtered analytically
// in board coordinates (separable soft edges), so corners are anti-aliased
// without bias: a corner lies where both soft signs cross zero.
#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

namespace rockface::test {

struct BoardCamera {
  cv::Size size{800, 600};
  cv::Matx33d K{700, 0, 405.3, 0, 702, 296.8, 0, 0, 1};
  cv::Vec<double, 5> dist{-0.12, 0.08, 0.0008, -0.0005, 0.0};
};

// cols x rows inner corners, square side s; board points (c s, r s, 0).
// R, t: x_cam = R x_board + t.
inline cv::Mat render_board_view(const BoardCamera& cam, int cols, int rows, double s,
                                 const cv::Matx33d& R, const cv::Vec3d& t) {
  const int W = cam.size.width, H = cam.size.height;
  std::vector<cv::Point2d> pixels;
  pixels.reserve(static_cast<size_t>(W) * H);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) pixels.emplace_back(u, v);
  std::vector<cv::Point2d> normalized;
  cv::undistortPoints(pixels, normalized, cam.K, cam.dist, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT, 10,
                                       0));  // converged to < 1e-5 px for this distortion
  // Board plane in camera coordinates: points R (X, Y, 0) + t.
  const cv::Vec3d n = R * cv::Vec3d(0, 0, 1);
  const cv::Matx33d Rt = R.t();
  cv::Mat X(H, W, CV_64F), Y(H, W, CV_64F), hit(H, W, CV_8U);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) {
      const cv::Point2d& q = normalized[static_cast<size_t>(v) * W + u];
      const cv::Vec3d ray(q.x, q.y, 1.0);
      const double denom = n.dot(ray);
      const double lambda = denom != 0 ? n.dot(t) / denom : -1;
      hit.at<uchar>(v, u) = lambda > 0;
      const cv::Vec3d b = Rt * (lambda * ray - t);
      X.at<double>(v, u) = b[0];
      Y.at<double>(v, u) = b[1];
    }
  // Soft sign of a square wave of period 2 s: +1 in even cells, -1 in odd
  // ones, linear across an edge over the pixel footprint w.
  auto soft = [s](double x, double w) {
    const double cell = std::floor(x / s);
    const double frac = x - cell * s;           // [0, s)
    const double d = std::min(frac, s - frac);  // distance to the nearest edge
    const double sign = (static_cast<long long>(cell) % 2 == 0) ? 1.0 : -1.0;
    const double ramp = std::clamp(2 * d / std::max(w, 1e-9), 0.0, 1.0);  // box filter of width w
    return sign * ramp;
  };
  cv::Mat image(H, W, CV_8U);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) {
      if (!hit.at<uchar>(v, u)) {
        image.at<uchar>(v, u) = 90;
        continue;
      }
      const int u1 = std::min(u + 1, W - 1), u0 = u1 - 1;
      const int v1 = std::min(v + 1, H - 1), v0 = v1 - 1;
      const double wx = std::abs(X.at<double>(v, u1) - X.at<double>(v, u0)) +
                        std::abs(X.at<double>(v1, u) - X.at<double>(v0, u));
      const double wy = std::abs(Y.at<double>(v, u1) - Y.at<double>(v, u0)) +
                        std::abs(Y.at<double>(v1, u) - Y.at<double>(v0, u));
      const double bx = X.at<double>(v, u), by = Y.at<double>(v, u);
      double value;
      // Squares span [-s, cols s] x [-s, rows s]; a white margin of one
      // square around them, grey beyond.
      if (bx < -2 * s || bx > (cols + 1) * s || by < -2 * s || by > (rows + 1) * s)
        value = 90;
      else if (bx < -s || bx > cols * s || by < -s || by > rows * s)
        value = 220;
      else
        value = 130 + 90 * soft(bx + s, wx) * soft(by + s, wy);
      image.at<uchar>(v, u) = cv::saturate_cast<uchar>(value);
    }
  return image;
}

// A symmetric grid of black circles (radius 0.3 of the spacing s) on a
// white board, cols x rows centres at (c s, r s, 0), edges anti-aliased over
// the pixel footprint (a radial ramp, symmetric, so centres are unbiased to
// first order).
inline cv::Mat render_circle_grid_view(const BoardCamera& cam, int cols, int rows, double s,
                                       const cv::Matx33d& R, const cv::Vec3d& t) {
  const int W = cam.size.width, H = cam.size.height;
  std::vector<cv::Point2d> pixels;
  pixels.reserve(static_cast<size_t>(W) * H);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) pixels.emplace_back(u, v);
  std::vector<cv::Point2d> normalized;
  cv::undistortPoints(pixels, normalized, cam.K, cam.dist, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT, 10, 0));
  const cv::Vec3d n = R * cv::Vec3d(0, 0, 1);
  const cv::Matx33d Rt = R.t();
  const double radius = 0.3 * s;
  cv::Mat image(H, W, CV_8U);
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) {
      const size_t i = static_cast<size_t>(v) * W + u;
      const cv::Vec3d ray(normalized[i].x, normalized[i].y, 1.0);
      const double lambda = n.dot(t) / n.dot(ray);
      const cv::Vec3d b = Rt * (lambda * ray - t);
      // Footprint of the pixel on the board: range over focal length,
      // stretched by the incidence.
      const double ray_norm = cv::norm(ray);
      const double footprint =
          lambda * ray_norm / cam.K(0, 0) / std::max(std::abs(n.dot(ray)) / ray_norm, 0.1);
      double value = 90;  // beyond the board
      if (lambda > 0 && b[0] > -s && b[0] < cols * s && b[1] > -s && b[1] < rows * s) {
        const double cx = std::clamp(std::round(b[0] / s), 0.0, cols - 1.0) * s;
        const double cy = std::clamp(std::round(b[1] / s), 0.0, rows - 1.0) * s;
        const double d = std::hypot(b[0] - cx, b[1] - cy);
        const double black = std::clamp((radius - d) / footprint + 0.5, 0.0, 1.0);
        value = 220 - 190 * black;
      }
      image.at<uchar>(v, u) = cv::saturate_cast<uchar>(value);
    }
  return image;
}

// Board pose looking at the board centre from `distance`, tilted by
// (ax, ay) about the board's x and y axes and turned by az in its plane.
inline void board_pose(int cols, int rows, double s, double ax, double ay, double az,
                       double distance, const cv::Vec3d& offset, cv::Matx33d& R, cv::Vec3d& t) {
  cv::Matx33d Rx, Ry, Rz;
  cv::Rodrigues(cv::Vec3d(ax, 0, 0), Rx);
  cv::Rodrigues(cv::Vec3d(0, ay, 0), Ry);
  cv::Rodrigues(cv::Vec3d(0, 0, az), Rz);
  R = Rx * Ry * Rz;
  const cv::Vec3d centre((cols - 1) * s / 2, (rows - 1) * s / 2, 0);
  t = cv::Vec3d(0, 0, distance) + offset - R * centre;
}

}  // namespace rockface::test
