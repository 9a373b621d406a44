// The terraces of semi-global matching smoothed back into their slope
// (disparity_terraces.h): a slope quantised into treads and risers comes
// back as the slope; an occlusion edge, risers that change direction and a
// slope already followed stay as they are.
#include "core/photogrammetry/matching/disparity_terraces.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace rockface::photogrammetry {
namespace {

// A wall seen along the drive: 0.6 px of disparity per column.
double slope(double x) {
  return 20.0 + 0.6 * x;
}

// The slope as SGBM leaves it: treads 6 px long at the slope's value at
// their centre, risers of 3.6 px between them.
cv::Mat terraced(int rows, int cols) {
  cv::Mat d(rows, cols, CV_32F);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) d.at<float>(y, x) = static_cast<float>(slope(6 * (x / 6) + 2.5));
  return d;
}

TEST(DisparityTerraces, ATerracedSlopeComesBackAsTheSlope) {
  cv::Mat d = terraced(10, 60);
  const std::size_t changed = smooth_disparity_terraces(d, {});
  EXPECT_GT(changed, 10u * 40u);
  // Between the first tread's centre (2.5) and the last one's (56.5) the
  // lines through the treads' centres are the slope itself, to the
  // rounding of floats (disparities ~50 px, float epsilon 1.2e-7 relative).
  for (int y = 0; y < d.rows; ++y)
    for (int x = 3; x <= 56; ++x) ASSERT_NEAR(d.at<float>(y, x), slope(x), 1e-4) << x << "," << y;
}

TEST(DisparityTerraces, AnOcclusionEdgeZigzagsAndAFollowedSlopeStay) {
  // One row each (a single row has no column long enough for a staircase).
  cv::Mat edge(1, 60, CV_32F), zigzag(1, 60, CV_32F), followed(1, 60, CV_32F);
  for (int x = 0; x < 60; ++x) {
    // Two surfaces 10 px apart in disparity (an occlusion edge, higher than
    // any riser), each with a tread of 5 px and a 2 px riser before the
    // edge: the edge breaks the staircase, which is too short on its own.
    edge.at<float>(0, x) = x < 25 ? 20.0f : x < 30 ? 22.0f : x < 35 ? 32.0f : 34.0f;
    // Risers of 2 px that change direction every tread (noise or relief,
    // not a staircase).
    zigzag.at<float>(0, x) = 20.0f + 2.0f * static_cast<float>(x / 4 % 2);
    // A slope SGBM followed (0.6 px a pixel: no riser at all).
    followed.at<float>(0, x) = static_cast<float>(slope(x));
  }
  for (cv::Mat* d : {&edge, &zigzag, &followed}) {
    const cv::Mat before = d->clone();
    EXPECT_EQ(smooth_disparity_terraces(*d, {}), 0u);
    for (int x = 0; x < 60; ++x) EXPECT_EQ(d->at<float>(0, x), before.at<float>(0, x)) << x;
  }
}

TEST(DisparityTerraces, UnknownPixelsBreakAStaircaseAndStayUnknown) {
  cv::Mat d = terraced(1, 60);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  d.at<float>(0, 30) = nan;
  smooth_disparity_terraces(d, {});
  EXPECT_TRUE(std::isnan(d.at<float>(0, 30)));
  // Each side is a staircase of its own: on the slope between its first
  // and last treads' centres (floats' rounding as above).
  for (int x = 3; x <= 26; ++x) EXPECT_NEAR(d.at<float>(0, x), slope(x), 1e-4) << x;
  for (int x = 39; x <= 56; ++x) EXPECT_NEAR(d.at<float>(0, x), slope(x), 1e-4) << x;
}

}  // namespace
}  // namespace rockface::photogrammetry
