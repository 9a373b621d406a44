// The shading of the two views (view_shading.h): one rock texture seen in
// two "views" shifted by a known disparity, the right one under a known
// brightness field. One exposure gain is no difference; a gain that changes
// across the face is measured as the spread of the ratio about it; dividing
// by the local brightness takes a slowly varying gain out.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/photogrammetry/matching/view_shading.h"
#include "tests/core/photogrammetry/noise_texture.h"

namespace {

using namespace rockface;
namespace rp = photogrammetry;

constexpr int kShift = 40;  // disparity, px

const cv::Mat& rock() {
  // Mean ~128, levels 30..230 so that a gain of 0.7..1.15 neither clips nor
  // falls into the dark.
  static const cv::Mat t = [] {
    cv::Mat g = test::noise_texture(900, 400, 5, 1.5, 8.0), out;
    g.convertTo(out, CV_8U, 200.0 / 255.0, 30);
    return out;
  }();
  return t;
}

// The right view: the rock shifted by kShift, times gain(x) of the left x.
cv::Mat right_view(double (*gain)(double)) {
  cv::Mat out(rock().rows, rock().cols - kShift, CV_8U);
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x)
      out.at<uchar>(y, x) =
          cv::saturate_cast<uchar>(rock().at<uchar>(y, x + kShift) * gain(x + kShift));
  return out;
}

cv::Mat left_view() {
  return rock()(cv::Rect(0, 0, rock().cols - kShift, rock().rows)).clone();
}

// Tie points on a grid, right = left - kShift.
void tie_points(std::vector<Eigen::Vector2d>& l, std::vector<Eigen::Vector2d>& r) {
  for (int y = 30; y < 370; y += 20)
    for (int x = 70; x < 820; x += 25) {
      l.emplace_back(x, y);
      r.emplace_back(x - kShift, y);
    }
}

double exposure(double) {
  return 0.8;
}
// 0.7 at the left edge to 1.15 at the right: a flash's ratio across a face.
double ramp(double x) {
  return 0.7 + 0.45 * x / 900.0;
}

TEST(ViewShading, OneExposureGainIsNoDifference) {
  std::vector<Eigen::Vector2d> l, r;
  tie_points(l, r);
  const rp::ViewShading s = rp::compare_view_shading(left_view(), right_view(exposure), l, r);
  ASSERT_TRUE(s.measured());
  // Rounding to 8 bits changes the ratio by under 1 % on levels of 30 and
  // more, averaged over the window: the spread stays far below the limit.
  EXPECT_NEAR(s.gain, 0.8, 0.01);
  EXPECT_LT(s.spread, 0.01);
  EXPECT_FALSE(rp::shading_differs(s));
}

TEST(ViewShading, AGainThatChangesAcrossTheFaceIsMeasured) {
  std::vector<Eigen::Vector2d> l, r;
  tie_points(l, r);
  const rp::ViewShading s = rp::compare_view_shading(left_view(), right_view(ramp), l, r);
  ASSERT_TRUE(s.measured());
  // The true spread: half the 10-90 % range of log gain at the tie points
  // (the same rock at left x has gain(x) in the right view), about 0.16.
  std::vector<double> log_gain;
  for (const auto& p : l) log_gain.push_back(std::log(ramp(p.x())));
  std::sort(log_gain.begin(), log_gain.end());
  const auto at = [&](double q) {
    return log_gain[static_cast<std::size_t>(std::lround(q * (log_gain.size() - 1)))];
  };
  const double truth = 0.5 * (at(0.9) - at(0.1));
  // The window (sigma 8 px) averages a gain that is linear in x, and 8-bit
  // rounding adds under 1 % per ratio: within 0.005 of the truth.
  EXPECT_NEAR(s.spread, truth, 0.005);
  EXPECT_TRUE(rp::shading_differs(s));
  EXPECT_NE(rp::shading_warning(s).find("light the face differently"), std::string::npos);
}

TEST(ViewShading, DividingByTheLocalBrightnessTakesTheGainOut) {
  const cv::Mat left = left_view(), right = right_view(ramp);
  const cv::Mat a = rp::normalise_local_brightness(left, rp::kShadingNormalisationSigmaPx);
  const cv::Mat b = rp::normalise_local_brightness(right, rp::kShadingNormalisationSigmaPx);
  // Before: the same rock differs by the gain (up to 30 % of ~128 grey).
  // After: the gain changes by 0.45 / 900 per px, 0.5 % over the window's
  // +-2 sigma, so the normalised views agree to a few grey levels (8-bit
  // rounding of the input and of the output).
  double before = 0, after = 0;
  int count = 0;
  for (int y = 20; y < a.rows - 20; y += 3)
    for (int x = kShift + 20; x < a.cols - 20; x += 3) {
      before += std::abs(left.at<uchar>(y, x) - right.at<uchar>(y, x - kShift));
      after += std::abs(a.at<uchar>(y, x) - b.at<uchar>(y, x - kShift));
      ++count;
    }
  before /= count;
  after /= count;
  EXPECT_GT(before, 10.0);
  EXPECT_LT(after, 2.0);
}

}  // namespace
