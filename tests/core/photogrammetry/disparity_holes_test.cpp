// Holes of a disparity map filled from their rims (disparity_holes.h): a
// slanted plane with holes comes back as the plane; a gap at an occlusion
// edge and a gap wider than the limit stay empty.
#include "core/photogrammetry/matching/disparity_holes.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace rockface::photogrammetry {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// A plane seen at a grazing angle: 0.6 px of disparity per column, 0.2 per
// row (a tunnel wall seen along the drive).
float plane(int x, int y) {
  return 20.0f + 0.6f * static_cast<float>(x) + 0.2f * static_cast<float>(y);
}

cv::Mat plane_map(int rows, int cols) {
  cv::Mat d(rows, cols, CV_32F);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) d.at<float>(y, x) = plane(x, y);
  return d;
}

TEST(DisparityHoles, HolesInASlantedPlaneComeBackOnThePlane) {
  cv::Mat d = plane_map(40, 60);
  // A 5 x 4 hole, a one-pixel hole and a row gap of 8 pixels (the limit).
  for (int y = 10; y < 14; ++y)
    for (int x = 20; x < 25; ++x) d.at<float>(y, x) = kNaN;
  d.at<float>(30, 40) = kNaN;
  for (int x = 5; x < 13; ++x) d.at<float>(2, x) = kNaN;
  const std::size_t filled = fill_disparity_holes(d, {});
  EXPECT_EQ(filled, 20u + 1u + 8u);
  // Linear interpolation of a plane between its rims is the plane, to the
  // rounding of floats (disparities ~60 px, float epsilon 1.2e-7 relative).
  for (int y = 0; y < d.rows; ++y)
    for (int x = 0; x < d.cols; ++x)
      ASSERT_NEAR(d.at<float>(y, x), plane(x, y), 1e-4) << x << "," << y;
}

TEST(DisparityHoles, AGapAtAnOcclusionEdgeOrWiderThanTheLimitStaysEmpty) {
  cv::Mat d = plane_map(20, 60);
  // An occlusion edge: the right part 12 px nearer, a 3-pixel gap between
  // (12 px across 4 steps is 3 px per pixel, beyond the 1 px slope).
  for (int y = 0; y < d.rows; ++y) {
    for (int x = 30; x < 60; ++x) d.at<float>(y, x) += 12.0f;
    for (int x = 27; x < 30; ++x) d.at<float>(y, x) = kNaN;
  }
  // A hole of 9 x 9 pixels: wider than the 8-pixel limit in both directions.
  for (int y = 5; y < 14; ++y)
    for (int x = 5; x < 14; ++x) d.at<float>(y, x) = kNaN;
  EXPECT_EQ(fill_disparity_holes(d, {}), 0u);
  EXPECT_TRUE(std::isnan(d.at<float>(10, 28)));
  EXPECT_TRUE(std::isnan(d.at<float>(9, 9)));
}

TEST(DisparityHoles, ALimitOfZeroFillsNothing) {
  cv::Mat d = plane_map(10, 10);
  d.at<float>(5, 5) = kNaN;
  EXPECT_EQ(fill_disparity_holes(d, {0, 1.0}), 0u);
  EXPECT_TRUE(std::isnan(d.at<float>(5, 5)));
}

}  // namespace
}  // namespace rockface::photogrammetry
