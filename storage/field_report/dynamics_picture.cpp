#include "storage/field_report/dynamics_picture.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/common/number_format.h"

namespace rockface::storage {

namespace {

// A scale bar length: 1, 2 or 5 x 10^k metres near a fifth of the span.
double nice_length(double span) {
  const double target = span / 5;
  const double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= target) return m * p;
  return 10 * p;
}

}  // namespace

std::vector<Eigen::Vector3d> posed_vertices(const std::vector<Eigen::Vector3d>& vertices,
                                            const ReportDynamics& d, const ReportMotionSample& s) {
  std::vector<Eigen::Vector3d> out;
  if (d.path.empty()) return out;
  const Eigen::Vector3d c0 = d.path.front().position;
  const Eigen::Quaterniond q(s.orientation(0), s.orientation(1), s.orientation(2),
                             s.orientation(3));
  for (const auto& v : vertices) out.push_back(s.position + q.normalized() * (v - c0));
  return out;
}

cv::Mat dynamics_picture(const std::string& block_id, const std::vector<Eigen::Vector3d>& vertices,
                         const ReportDynamics& d, int width, int height) {
  if (d.path.empty() || vertices.empty()) return {};
  const Eigen::Vector3d origin = d.path.front().position;
  const Eigen::Vector3d travel = d.path.back().position - origin;
  const Eigen::Vector2d level(travel(0), travel(1));
  // Side view unless it moves mostly level (then a plan view shows more).
  const bool side = std::abs(travel(2)) >= 0.2 * level.norm() || level.norm() == 0;
  Eigen::Vector3d across = Eigen::Vector3d::UnitX();
  if (level.norm() > 1e-9 * (1 + travel.norm()))
    across = Eigen::Vector3d(level(0), level(1), 0).normalized();
  auto project = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d r = x - origin;
    return side ? Eigen::Vector2d(r.dot(across), r(2)) : Eigen::Vector2d(r(0), r(1));
  };
  // The poses drawn: about a dozen at regular times, and the last.
  const size_t n = d.path.size();
  const size_t every = std::max<size_t>(1, (n + 11) / 12);
  std::vector<size_t> shown;
  for (size_t i = 0; i < n; i += every) shown.push_back(i);
  if (shown.back() != n - 1) shown.push_back(n - 1);
  std::vector<std::vector<Eigen::Vector2d>> outlines;
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (size_t i : shown) {
    std::vector<Eigen::Vector2d> pts;
    for (const auto& v : posed_vertices(vertices, d, d.path[i])) {
      pts.push_back(project(v));
      lo = lo.cwiseMin(pts.back());
      hi = hi.cwiseMax(pts.back());
    }
    outlines.push_back(pts);
  }
  const Eigen::Vector2d span = (hi - lo).cwiseMax(1e-6);
  const double margin = 0.08 * span.maxCoeff();
  lo -= Eigen::Vector2d::Constant(margin);
  hi += Eigen::Vector2d::Constant(margin);
  // The floor's trace in the side view.
  std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> floor_line;
  if (side && d.floor) {
    const Eigen::Vector3d p = d.floor->first - origin, nrm = d.floor->second;
    if (std::abs(nrm(2)) > 1e-6) {
      auto z_at = [&](double s) {
        const Eigen::Vector3d x = s * across;
        return p(2) - (nrm.dot(x - p) - nrm(2) * (x(2) - p(2))) / nrm(2);
      };
      floor_line =
          std::make_pair(Eigen::Vector2d(lo(0), z_at(lo(0))), Eigen::Vector2d(hi(0), z_at(hi(0))));
      lo(1) = std::min({lo(1), floor_line->first(1) - margin, floor_line->second(1) - margin});
      hi(1) = std::max({hi(1), floor_line->first(1), floor_line->second(1)});
    }
  }
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const int top = 40, bottom = 40, left = 20, right = 20;
  const double scale =
      std::min((width - left - right) / (hi(0) - lo(0)), (height - top - bottom) / (hi(1) - lo(1)));
  auto pixel = [&](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::lround(left + (p(0) - lo(0)) * scale)),
                     static_cast<int>(std::lround(height - bottom - (p(1) - lo(1)) * scale)));
  };
  const cv::Scalar ink(40, 40, 40), ground(60, 110, 150);
  if (floor_line) {
    const cv::Point a = pixel(floor_line->first), b = pixel(floor_line->second);
    cv::line(img, a, b, ground, 3, cv::LINE_AA);
    cv::putText(img, "floor", a + cv::Point(6, 18), cv::FONT_HERSHEY_SIMPLEX, 0.5, ground, 1,
                cv::LINE_AA);
  }
  for (size_t k = 0; k < outlines.size(); ++k) {
    std::vector<cv::Point2f> pts;
    for (const auto& p : outlines[k]) {
      const cv::Point q = pixel(p);
      pts.emplace_back(static_cast<float>(q.x), static_cast<float>(q.y));
    }
    std::vector<cv::Point2f> hull;
    cv::convexHull(pts, hull);
    std::vector<cv::Point> poly;
    for (const auto& h : hull) poly.emplace_back(cvRound(h.x), cvRound(h.y));
    // Early poses blue, late ones red; the start bold.
    const double f = outlines.size() > 1 ? static_cast<double>(k) / (outlines.size() - 1) : 0.0;
    const cv::Scalar colour(200 * (1 - f), 40, 40 + 200 * f);
    cv::polylines(img, poly, true, colour, k == 0 ? 3 : 2, cv::LINE_AA);
    cv::Point label = poly.front();
    for (const auto& q : poly)
      if (q.y < label.y) label = q;
    cv::putText(img, format_fixed(d.path[shown[k]].time_s, 2, " s"), label + cv::Point(4, -4),
                cv::FONT_HERSHEY_SIMPLEX, 0.45, colour, 1, cv::LINE_AA);
  }
  // Title, view, scale bar.
  std::string title =
      block_id + ": motion after failure, " +
      (side ? "side view (horizontal towards N" +
                  format_fixed(std::fmod(std::atan2(across(0), across(1)) * 180 / M_PI + 360, 360),
                               0, "E") +
                  ")"
            : std::string("plan view (north up)"));
  cv::putText(img, title, {left, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.55, ink, 1, cv::LINE_AA);
  const double bar = nice_length(hi(0) - lo(0));
  const cv::Point b0(left, height - 14),
      b1(left + static_cast<int>(std::lround(bar * scale)), height - 14);
  cv::line(img, b0, b1, ink, 2);
  cv::putText(img, format_significant(bar, 6, " m"), b1 + cv::Point(6, 5), cv::FONT_HERSHEY_SIMPLEX,
              0.45, ink, 1, cv::LINE_AA);
  if (d.landing)
    cv::putText(
        img,
        "lands at " + format_fixed(d.landing->speed, 1, " m/s") + ", " +
            format_fixed((d.landing->kinetic_translational + d.landing->kinetic_rotational) / 1000,
                         0, " kJ"),
        {width / 2, height - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1, cv::LINE_AA);
  return img;
}

}  // namespace rockface::storage
