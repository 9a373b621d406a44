// Issue 38: holes of the developed view filled from measured neighbours
// (core/tunnel/lining_interpolation.h), on small hand-made grids whose
// answers are worked out by hand below.
#include "core/tunnel/lining_interpolation.h"

#include <gtest/gtest.h>

#include <vector>

namespace rockface::tunnel {
namespace {

// 5 rows (chainage, 0.25 m apart) x 8 columns (outline, 0.05 m apart, wrapping).
constexpr std::size_t kRows = 5, kCols = 8;
const NeighbourSpacing kSpacing{0.25, 0.05};

struct Grid {
  std::vector<double> normal = std::vector<double>(kRows * kCols, 0.0);
  std::vector<double> ray = std::vector<double>(kRows * kCols, 0.0);
  std::vector<std::uint8_t> measured = std::vector<std::uint8_t>(kRows * kCols, 1);
  std::vector<std::uint8_t> fillable = std::vector<std::uint8_t>(kRows * kCols, 0);
  void hole(std::size_t r, std::size_t c) {
    measured[r * kCols + c] = 0;
    fillable[r * kCols + c] = 1;
  }
  std::vector<FilledCell> fill(double max_hole_m) const {
    return fill_lining_holes(kRows, kCols, normal, ray, measured, fillable, kSpacing, max_hole_m);
  }
};

TEST(LiningHoles, AHoleAcrossTheOutlinesSeamIsFilledLinearlyBetweenItsEnds) {
  Grid g;
  // Row 2: columns 7 and 0 unseen, between column 6 (0.10 m) and column 1
  // (0.40 m) across the seam; along the chainage rows 1 and 3 are 0.2 m
  // at both columns.
  for (std::size_t c = 0; c < kCols; ++c) g.normal[2 * kCols + c] = g.ray[2 * kCols + c] = 0.1;
  g.normal[2 * kCols + 1] = g.ray[2 * kCols + 1] = 0.4;
  for (std::size_t r : {1u, 3u})
    for (std::size_t c : {7u, 0u}) g.normal[r * kCols + c] = g.ray[r * kCols + c] = 0.2;
  g.hole(2, 7);
  g.hole(2, 0);
  const auto filled = g.fill(0.5);
  ASSERT_EQ(filled.size(), 2u);
  for (const FilledCell& f : filled) {
    // Along the outline: 0.1 + (0.4 - 0.1) x 1/3 at column 7, x 2/3 at
    // column 0, over a hole of 2 cells (0.10 m), weight 1 / 0.15; along the
    // chainage 0.2 over a hole of one cell (0.25 m), weight 1 / 0.5.
    const double along_s = f.cell == 2 * kCols + 7 ? 0.2 : 0.3;
    const double expected = (along_s / 0.15 + 0.2 / 0.5) / (1 / 0.15 + 1 / 0.5);
    EXPECT_NEAR(f.normal_m, expected, 1e-12);
    EXPECT_NEAR(f.ray_m, expected, 1e-12);
    // Half the spread of the cells it rests on: 0.1 to 0.4.
    EXPECT_NEAR(f.sigma_m, 0.15, 1e-12);
    EXPECT_NEAR(f.hole_m, 0.25, 1e-12);
  }
}

TEST(LiningHoles, NothingIsFilledBeyondTheMeasuredStretchOrAcrossAWiderHole) {
  Grid g;
  // The first row's column 3: no measured cell before it along the
  // chainage; along the outline its whole row is unseen (a hole of the
  // whole outline): not filled.
  for (std::size_t c = 0; c < kCols; ++c) g.hole(0, c);
  // Rows 1-3 of column 5 unseen: 0.75 m along the chainage; along the
  // outline columns 4 and 6 bracket it at 0.05 m.
  for (std::size_t r = 1; r <= 3; ++r) g.hole(r, 5);
  EXPECT_EQ(g.fill(0.5).size(), 3u);  // column 5 along the outline only
  // With a limit below one cell nothing is filled at all.
  EXPECT_TRUE(g.fill(0.04).empty());
  EXPECT_TRUE(g.fill(0).empty());
  // Column 4 unseen too: the outline's hole is 0.10 m, still within 0.5.
  for (std::size_t r = 1; r <= 3; ++r) g.hole(r, 4);
  EXPECT_EQ(g.fill(0.5).size(), 6u);
  EXPECT_EQ(g.fill(0.06).size(), 0u);
}

}  // namespace
}  // namespace rockface::tunnel
