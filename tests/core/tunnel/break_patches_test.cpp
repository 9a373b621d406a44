// The robust patch rule (break_patches.h): a break patch wider than the
// rectangle keeps every counted cell, flanks included; a band narrower
// than the rectangle in either direction counts for nothing; a cell with
// no value inside a patch does not cut it; patches of opposite sign do not
// hold each other up; the outline wraps; the rectangle lies inside the
// round.
#include "core/tunnel/break_patches.h"

#include <gtest/gtest.h>

namespace rockface::tunnel {
namespace {

struct View {
  std::size_t rows, cols;
  std::vector<std::int8_t> sign;
  std::vector<std::uint8_t> valued;
  View(std::size_t r, std::size_t c) : rows(r), cols(c), sign(r * c, 0), valued(r * c, 1) {}
  void fill(std::size_t r0, std::size_t r1, std::size_t c0, std::size_t c1, std::int8_t s) {
    for (std::size_t r = r0; r <= r1; ++r)
      for (std::size_t c = c0; c <= c1; ++c) sign[r * cols + c % cols] = s;
  }
  int count(const std::vector<std::int8_t>& v, std::int8_t s) const {
    int n = 0;
    for (auto x : v) n += x == s ? 1 : 0;
    return n;
  }
};

TEST(BreakPatches, AWidePatchKeepsEveryCellAndANarrowBandNone) {
  View v(20, 60);
  // A break 6 sections by 12 rays, with a spur of one ray on two of its
  // sections (narrower than the rectangle: it goes, the break stays whole);
  // an underbreak band 2 sections long (narrower than 3) and another 4 rays
  // wide (narrower than 5).
  v.fill(2, 7, 10, 21, 1);
  v.fill(4, 5, 22, 22, 1);
  v.fill(12, 13, 5, 40, -1);
  v.fill(2, 18, 50, 53, -1);
  const auto kept = open_break_patches(v.rows, v.cols, v.sign, v.valued, {1, 2});
  EXPECT_EQ(v.count(kept, 1), 6 * 12);
  EXPECT_EQ(v.count(kept, -1), 0);
  // The same bands one section / one ray wider are kept whole.
  v.fill(14, 14, 5, 40, -1);
  v.fill(2, 18, 54, 54, -1);
  const auto wider = open_break_patches(v.rows, v.cols, v.sign, v.valued, {1, 2});
  EXPECT_EQ(v.count(wider, -1), 3 * 36 + 17 * 5);
}

TEST(BreakPatches, AHoleInsideAPatchDoesNotCutItAndSignsDoNotMix) {
  View v(10, 30);
  // An overbreak 3 sections by 7 rays with one unseen cell in its middle:
  // the rectangles on either side of the hole fit (the hole is not held
  // against them), so every counted cell is kept.
  v.fill(2, 4, 3, 9, 1);
  v.sign[3 * 30 + 6] = 0;
  v.valued[3 * 30 + 6] = 0;
  // An overbreak 3 x 3 beside an underbreak 3 x 3: together 3 x 6, yet
  // neither is 5 rays wide: both go.
  v.fill(5, 7, 15, 17, 1);
  v.fill(5, 7, 18, 20, -1);
  const auto kept = open_break_patches(v.rows, v.cols, v.sign, v.valued, {1, 2});
  EXPECT_EQ(v.count(kept, 1), 21 - 1);
  EXPECT_EQ(v.count(kept, -1), 0);
}

TEST(BreakPatches, TheOutlineWraps) {
  // A patch 3 rays either side of column 0 (columns 37-39 and 0-2 of 40).
  View v(5, 40);
  v.fill(1, 3, 37, 42, -1);
  const auto kept = open_break_patches(v.rows, v.cols, v.sign, v.valued, {1, 2});
  EXPECT_EQ(v.count(kept, -1), 3 * 6);
}

TEST(BreakPatches, ABandAtTheRoundsEndsShorterThanTheRectangleDoesNotCount) {
  // The rectangle (3 sections) must lie inside the round: a band in the
  // last two sections (the crease by the face) counts for nothing, and so
  // does one in the first two; a break of 4 sections running into the
  // round's end keeps all of its cells, the end section included.
  View v(12, 40);
  v.fill(10, 11, 2, 12, -1);
  v.fill(0, 1, 20, 30, 1);
  v.fill(0, 3, 32, 38, -1);
  const auto kept = open_break_patches(v.rows, v.cols, v.sign, v.valued, {1, 2});
  EXPECT_EQ(v.count(kept, 1), 0);
  EXPECT_EQ(v.count(kept, -1), 4 * 7);
  // A round of two sections (shorter than the rectangle) takes the
  // rectangle as long as it is: a patch across both counts.
  View short_round(2, 40);
  short_round.fill(0, 1, 5, 15, 1);
  const auto whole = open_break_patches(short_round.rows, short_round.cols, short_round.sign,
                                        short_round.valued, {1, 2});
  EXPECT_EQ(short_round.count(whole, 1), 2 * 11);
}

TEST(BreakPatches, TheRectangleIsTheLargestOddCountOfCellsWithinTheSize) {
  // The standard preset's cells: 0.245 m of chainage, 0.05 m of outline.
  const PatchSize s = patch_size_for(0.75, 0.25, 0.245, 0.05);
  EXPECT_EQ(s.half_rows, 1u);  // 3 x 0.245 = 0.735 m (5 would be 1.225)
  EXPECT_EQ(s.half_cols, 2u);  // 5 x 0.05 = 0.25 m exactly
  // The fast preset's 0.5 x 0.1 m cells: one section, 1 + 2 rays.
  const PatchSize f = patch_size_for(0.75, 0.25, 0.5, 0.1);
  EXPECT_EQ(f.half_rows, 0u);
  EXPECT_EQ(f.half_cols, 1u);
  // 0: a single cell, every counted cell kept.
  const PatchSize z = patch_size_for(0, 0, 0.245, 0.05);
  EXPECT_EQ(z.half_rows, 0u);
  EXPECT_EQ(z.half_cols, 0u);
}

TEST(BreakPatches, MismatchedSizesAreRefused) {
  EXPECT_THROW(
      open_break_patches(2, 2, std::vector<std::int8_t>(3, 0), std::vector<std::uint8_t>(4, 1), {}),
      std::exception);
}

}  // namespace
}  // namespace rockface::tunnel
