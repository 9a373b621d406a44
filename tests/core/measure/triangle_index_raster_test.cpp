// The surface image's triangle fill (proposals/triangle_index_raster.h)
// against its rule worked out another way: a pixel is drawn with a triangle
// when any point of its square, sampled on the 1/16 px grid the corners lie
// on, is in the closed triangle by exact integer tests written here. On a
// jittered lattice of triangles like the reconstruction's, every pixel of
// the region it tiles is covered and none beyond half a pixel of it; the
// image cut into stripes gives the same pixels.
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "core/measure/proposals/triangle_index_raster.h"

namespace {

namespace pr = rockface::measure::proposals;
constexpr int kOne = 1 << pr::kRasterShift;

struct Lattice {
  std::vector<cv::Point> corners;  // 1/16 px
  std::vector<std::array<int, 3>> triangles;
  cv::Rect2i outline;  // the rectangle its border vertices lie on, 1/16 px
};

// A cols x rows lattice of `step_px` squares from (origin, origin), each cut
// into two triangles along alternating diagonals; inner vertices moved by up
// to `jitter` sixteenths each way (no triangle turns over while two corners'
// moves, each up to jitter * sqrt(2), stay short of the step / sqrt(2) from a
// corner to the diagonal across).
Lattice jittered_lattice(int cols, int rows, int step_px, int origin, int jitter, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> move(-jitter, jitter);
  Lattice l;
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= cols; ++c) {
      cv::Point p(origin + c * step_px * kOne, origin + r * step_px * kOne);
      if (r > 0 && r < rows && c > 0 && c < cols) p += cv::Point(move(random), move(random));
      l.corners.push_back(p);
    }
  const auto at = [&](int r, int c) { return r * (cols + 1) + c; };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      if ((r + c) % 2 == 0) {
        l.triangles.push_back({at(r, c), at(r, c + 1), at(r + 1, c + 1)});
        l.triangles.push_back({at(r, c), at(r + 1, c + 1), at(r + 1, c)});
      } else {
        l.triangles.push_back({at(r, c), at(r, c + 1), at(r + 1, c)});
        l.triangles.push_back({at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)});
      }
    }
  l.outline = cv::Rect2i(origin, origin, cols * step_px * kOne, rows * step_px * kOne);
  return l;
}

// Twice the signed area of (a, b, p), exactly.
std::int64_t side(const cv::Point& a, const cv::Point& b, const cv::Point& p) {
  return static_cast<std::int64_t>(b.x - a.x) * (p.y - a.y) -
         static_cast<std::int64_t>(b.y - a.y) * (p.x - a.x);
}

// Whether p lies in the closed triangle t.
bool holds(const std::array<cv::Point, 3>& t, const cv::Point& p) {
  std::int64_t s[3] = {side(t[0], t[1], p), side(t[1], t[2], p), side(t[2], t[0], p)};
  if (side(t[0], t[1], t[2]) < 0)
    for (auto& v : s) v = -v;
  return s[0] >= 0 && s[1] >= 0 && s[2] >= 0;
}

// Whether the square of pixel (x, y) reaches t: any of its 17 x 17 points on
// the 1/16 px grid, its border included, in t. Exact for the lattice's
// triangles, which are wider than a sixteenth everywhere a square meets them.
bool reaches(const std::array<cv::Point, 3>& t, int x, int y) {
  for (int dy = -kOne / 2; dy <= kOne / 2; ++dy)
    for (int dx = -kOne / 2; dx <= kOne / 2; ++dx)
      if (holds(t, cv::Point(x * kOne + dx, y * kOne + dy))) return true;
  return false;
}

std::array<cv::Point, 3> corners_of(const Lattice& l, std::size_t i) {
  const auto& t = l.triangles[i];
  return {l.corners[static_cast<std::size_t>(t[0])], l.corners[static_cast<std::size_t>(t[1])],
          l.corners[static_cast<std::size_t>(t[2])]};
}

cv::Mat draw_all(const Lattice& l, cv::Size size, const std::vector<int>& cuts) {
  cv::Mat shown(size, CV_32S, cv::Scalar(-1));
  std::vector<int> bounds = cuts;
  bounds.insert(bounds.begin(), 0);
  bounds.push_back(size.height);
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    cv::Mat rows = shown.rowRange(bounds[k], bounds[k + 1]);
    for (std::size_t i = 0; i < l.triangles.size(); ++i) {
      const auto c = corners_of(l, i);
      pr::draw_triangle_index(rows, bounds[k], c.data(), static_cast<int>(i));
    }
  }
  return shown;
}

TEST(TriangleIndexRaster, EachTriangleDrawsThePixelsItsSquaresReachAndTheLatticeLeavesNoGap) {
  // 3 px squares, corners moved by up to 0.69 px (11 sixteenths, below the
  // 0.75 px at which a triangle could turn over): triangles of two to seven
  // pixels whose edges and corners fall on pixels' borders and corners (the
  // border's vertices sit on pixel centres: origin 2 px, steps of 3 px).
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Lattice l = jittered_lattice(16, 10, 3, 2 * kOne, 11, seed);
    const cv::Size size(54, 36);
    cv::Mat any(size, CV_8U, cv::Scalar(0));
    for (std::size_t i = 0; i < l.triangles.size(); ++i) {
      cv::Mat alone(size, CV_32S, cv::Scalar(-1));
      const auto c = corners_of(l, i);
      pr::draw_triangle_index(alone, 0, c.data(), static_cast<int>(i));
      for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
          const bool drawn = alone.at<int>(y, x) == static_cast<int>(i);
          ASSERT_EQ(drawn, reaches(c, x, y))
              << "seed " << seed << " triangle " << i << " pixel " << x << "," << y;
          if (drawn) any.at<std::uint8_t>(y, x) = 1;
        }
    }
    // The lattice tiles its rectangle: a pixel is covered exactly when its
    // square reaches the rectangle (its centre within half a pixel of it).
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        const int cx = x * kOne, cy = y * kOne, h = kOne / 2;
        const bool near = cx + h >= l.outline.x && cx - h <= l.outline.x + l.outline.width &&
                          cy + h >= l.outline.y && cy - h <= l.outline.y + l.outline.height;
        EXPECT_EQ(any.at<std::uint8_t>(y, x), near ? 1 : 0)
            << "seed " << seed << " at " << x << "," << y;
      }
  }
}

TEST(TriangleIndexRaster, StripesDrawnApartGiveTheWholeImagesPixels) {
  const Lattice l = jittered_lattice(30, 20, 2, kOne + 5, 7, 7);
  const cv::Size size(64, 44);
  const cv::Mat whole = draw_all(l, size, {});
  const cv::Mat cut = draw_all(l, size, {7, 8, 21, 30});
  cv::Mat differ;
  cv::compare(whole, cut, differ, cv::CMP_NE);
  EXPECT_EQ(cv::countNonZero(differ), 0);
  EXPECT_GT(cv::countNonZero(whole >= 0), 2000);  // the lattice is drawn: 62 x 42 pixels
}

TEST(TriangleIndexRaster, ATriangleWithoutAreaOrOffTheImageDrawsNothing) {
  cv::Mat shown(10, 10, CV_32S, cv::Scalar(-1));
  const cv::Point line[3] = {{0, 0}, {5 * kOne, 5 * kOne}, {9 * kOne, 9 * kOne}};
  pr::draw_triangle_index(shown, 0, line, 3);
  const cv::Point off[3] = {{-40 * kOne, 0}, {-20 * kOne, 0}, {-30 * kOne, 9 * kOne}};
  pr::draw_triangle_index(shown, 0, off, 4);
  // Rows 20-29 of a larger image: this stripe holds none of them.
  const cv::Point below[3] = {{0, 20 * kOne}, {9 * kOne, 20 * kOne}, {0, 29 * kOne}};
  pr::draw_triangle_index(shown, 0, below, 5);
  EXPECT_EQ(cv::countNonZero(shown >= 0), 0);
}

}  // namespace
