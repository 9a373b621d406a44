// Dense matching of a surface seen at a grazing angle (slanted_passes.h,
// issue 38): a rectified pair of a wall whose disparity falls by 0.5 px per
// column (a tunnel's left wall seen along the drive), drawn from one texture
// so that the truth is the slope itself, never the matcher's output.
#include "core/photogrammetry/matching/slanted_passes.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/matching/dense_matching.h"
#include "core/photogrammetry/reconstruction/preset.h"

namespace rockface::photogrammetry {
namespace {

constexpr int kCols = 360, kRows = 160;
constexpr double kCentre = (kCols - 1) / 2.0;
constexpr double kSlope = -0.5;  // disparity change per column

// The wall's true disparity at column x of the left image.
double true_disparity(double x) {
  return 60.0 + kSlope * (x - kCentre);
}

// A rock-like texture: noise blurred to blobs of a few pixels, drawn at any
// column u by linear interpolation (so both views sample one surface).
cv::Mat texture() {
  cv::Mat t(kRows, 4 * kCols, CV_32F);
  cv::RNG rng(38);
  rng.fill(t, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(t, t, cv::Size(), 1.5);
  cv::normalize(t, t, 10, 245, cv::NORM_MINMAX);
  return t;
}

// The view of the texture where image column x shows texture column
// u(x) = offset + x * stretch.
cv::Mat view(const cv::Mat& t, double offset, double stretch) {
  cv::Mat mx(kRows, kCols, CV_32F), my(kRows, kCols, CV_32F), out;
  for (int y = 0; y < kRows; ++y)
    for (int x = 0; x < kCols; ++x) {
      mx.at<float>(y, x) = static_cast<float>(offset + x * stretch);
      my.at<float>(y, x) = static_cast<float>(y);
    }
  cv::remap(t, out, mx, my, cv::INTER_LINEAR);
  out.convertTo(out, CV_8U);
  return out;
}

// Of the pixels whose match lies inside the right image (away from the
// matching window's margin), the fraction whose disparity is within 0.5 px
// of the truth: at 0.5 px the wall's points lie within 2 % of their depth.
double fraction_within_half_a_pixel(const cv::Mat& d) {
  int inside = 0, right = 0;
  for (int y = 8; y < kRows - 8; ++y)
    for (int x = 8; x < kCols - 8; ++x) {
      const double xr = x - true_disparity(x);
      if (xr < 8 || xr > kCols - 9) continue;
      ++inside;
      const float v = d.at<float>(y, x);
      if (!std::isnan(v) && std::abs(v - true_disparity(x)) < 0.5) ++right;
    }
  return inside ? static_cast<double>(right) / inside : 0;
}

TEST(SlantedPasses, AWallSeenAtAGrazingAngleIsMatchedAlongItsSlope) {
  const cv::Mat t = texture();
  // Left: texture column = x + 400. Right column x_r shows the wall point
  // of left column x with x_r = x - d(x) = (1 - s) x - 60 + s xc, so
  // x = (x_r + 60 - s xc) / (1 - s).
  const cv::Mat left = view(t, 400, 1.0);
  const double a = 1.0 / (1.0 - kSlope);
  const cv::Mat right = view(t, 400 + (60 - kSlope * kCentre) * a, a);
  NoProgress quiet;
  const ReconstructionPreset preset = preset_standard();
  const cv::Mat first = match_rectified(left, right, {-48, 208}, preset, quiet).disparity;
  const SlantedResult slanted =
      match_slanted(right, first, {}, [&](const cv::Mat& warped, const SlantedRange& r) {
        return match_rectified(left, warped, {r.min_disparity, r.num_disparities}, preset, quiet)
            .disparity;
      });
  // SGBM alone matched 31 % of these pixels within half a pixel (terraces
  // and holes); the pass whose warp fits the wall matches it as a
  // fronto-parallel surface.
  EXPECT_GT(slanted.passes_run, 0);
  EXPECT_GT(fraction_within_half_a_pixel(slanted.disparity), 0.9);
}

TEST(SlantedPasses, TheWarpMakesASurfaceOfItsSlopeFrontoParallel) {
  // A right image whose column x shows the value x: after the warp for a
  // slope (s, t), column x' of row y shows the right image's column
  // xc + (1 - s)(x' - xc) - t (y - yc), the warp's definition.
  cv::Mat right(kRows, kCols, CV_32F);
  for (int y = 0; y < kRows; ++y)
    for (int x = 0; x < kCols; ++x) right.at<float>(y, x) = static_cast<float>(x);
  const DisparitySlope s{-0.5, 0.25};
  const cv::Mat w = warp_for_slope(right, s);
  const double yc = (kRows - 1) / 2.0;
  for (int y = 0; y < kRows; y += 7)
    for (int x = 0; x < kCols; x += 5) {
      const double expected =
          kCentre + (1 - s.along_row) * (x - kCentre) - s.along_column * (y - yc);
      if (expected < 0 || expected > kCols - 1) continue;
      // Linear interpolation of a linear ramp is exact to float rounding
      // (values below 360, float epsilon 1.2e-7 relative).
      ASSERT_NEAR(w.at<float>(y, x), expected, 1e-3) << x << "," << y;
    }
}

}  // namespace
}  // namespace rockface::photogrammetry
