// Semi-automatic tracing on images with a known trace.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/measure/least_cost_trace.h"

namespace rm = rockface::measure;

namespace {

// A rock-like texture (blurred noise) with a dark curved line drawn on it.
cv::Mat textured(int w, int h, int seed) {
  cv::Mat a(h, w, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(a, cv::RNG::UNIFORM, 60, 200);
  cv::GaussianBlur(a, a, cv::Size(0, 0), 1.5);
  return a;
}

std::vector<cv::Point2d> true_curve(int w, int h) {
  std::vector<cv::Point2d> c;
  for (int i = 0; i <= 200; ++i) {
    const double x = 40 + (w - 80) * i / 200.0;
    c.emplace_back(x, 0.5 * h + 40 * std::sin(x / 60.0));
  }
  return c;
}

double distance_to(const std::vector<cv::Point2d>& curve, const Eigen::Vector2d& p) {
  double best = 1e9;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const Eigen::Vector2d a(curve[i - 1].x, curve[i - 1].y), b(curve[i].x, curve[i].y);
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return best;
}

}  // namespace

TEST(LeastCostTrace, FollowsADarkTrace) {
  const int w = 500, h = 300;
  cv::Mat img = textured(w, h, 4);
  const auto curve = true_curve(w, h);
  std::vector<cv::Point> drawn;
  for (const auto& p : curve) drawn.emplace_back(cvRound(p.x * 16), cvRound(p.y * 16));
  cv::polylines(img, drawn, false, cv::Scalar(20), 3, cv::LINE_AA, 4);
  rm::TraceRequest r;
  r.from = {curve.front().x, curve.front().y};
  r.to = {curve.back().x, curve.back().y};
  const auto path = rm::trace_between(img, nullptr, r, "traces[0]");
  double sum = 0;
  for (const auto& p : path.pixels) sum += distance_to(curve, p);
  // The path runs on whole pixels along a 3 px line: ~0.3 px from its centre.
  EXPECT_LT(sum / static_cast<double>(path.pixels.size()), 1.0);
  EXPECT_GT(path.pixels.size(), 400u);
  EXPECT_LT(path.mean_cost, 0.3);  // on the dark line, not across the texture
}

TEST(LeastCostTrace, GradientCostFollowsAnEdge) {
  const int w = 300, h = 200;
  cv::Mat img = textured(w, h, 9) * 0.3;
  // A bright region below a diagonal edge y = 60 + 0.3 x.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (y > 60 + 0.3 * x) img.at<std::uint8_t>(y, x) += 150;
  rm::TraceRequest r;
  r.from = {20, 66};
  r.to = {280, 144};
  r.cost = rm::TraceCost::Gradient;
  const auto path = rm::trace_between(img, nullptr, r, "t");
  double sum = 0;
  for (const auto& p : path.pixels)
    sum += std::abs(p.y() - (60 + 0.3 * p.x())) / std::hypot(1, 0.3);
  // The Sobel response peaks on the two pixel rows either side of the step.
  EXPECT_LT(sum / static_cast<double>(path.pixels.size()), 1.5);
}

TEST(LeastCostTrace, BadEndsAreNamed) {
  const cv::Mat img = textured(100, 80, 1);
  auto message = [&](Eigen::Vector2d from, Eigen::Vector2d to, rm::TraceCost cost) {
    rm::TraceRequest r;
    r.from = from;
    r.to = to;
    r.cost = cost;
    try {
      rm::trace_between(img, nullptr, r, "traces[7]");
    } catch (const rockface::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({10, 10}, {150, 10}, rm::TraceCost::Darkness).find("traces[7].to"),
            std::string::npos);
  EXPECT_NE(message({std::nan(""), 10}, {50, 10}, rm::TraceCost::Darkness).find("traces[7].from"),
            std::string::npos);
  EXPECT_NE(message({10, 10}, {10.2, 10}, rm::TraceCost::Darkness).find("same pixel"),
            std::string::npos);
  EXPECT_NE(message({10, 10}, {50, 10}, rm::TraceCost::Curvature).find("3D image"),
            std::string::npos);
  EXPECT_THROW(rm::trace_cost_by_name("brightness", "cost"), rockface::InputError);
  EXPECT_EQ(rm::trace_cost_by_name("curvature", "cost"), rm::TraceCost::Curvature);
}
