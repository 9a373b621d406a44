// The chain helpers of trace proposals (proposals/line_chains.h) on small
// skeleton images drawn pixel by pixel here: the lines' ends and the pixels
// they cover are known from the drawing, so every expected chain is read
// off the drawing, not off the code. Covered: a line traced end to end,
// the minimum-length filter, a line followed through a crossing (at right
// angles and at 45 deg) and through a T, gaps joined when the line runs on
// and left open when it does not.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/measure/proposals/line_chains.h"

namespace {

namespace pr = rockface::measure::proposals;

// The turn and gap trace_proposals.cpp uses (kJoinTurnDeg; a gap of a few
// line widths).
constexpr double kTurnDeg = 30.0;
constexpr double kGapPx = 5.0;

cv::Mat blank() {
  return cv::Mat::zeros(80, 80, CV_8U);
}

// One pixel wide, drawn by hand: from (x0, y0) in `steps` steps of (dx, dy)
// (each -1, 0 or 1), both ends included.
void draw(cv::Mat& img, int x0, int y0, int dx, int dy, int steps) {
  for (int i = 0; i <= steps; ++i) img.at<std::uint8_t>(y0 + i * dy, x0 + i * dx) = 255;
}

bool same(cv::Point2f p, int x, int y) {
  return p.x == static_cast<float>(x) && p.y == static_cast<float>(y);
}

// The chain runs from (x0, y0) to (x1, y1), in either direction.
bool ends_at(const pr::Chain& c, int x0, int y0, int x1, int y1) {
  return (same(c.front(), x0, y0) && same(c.back(), x1, y1)) ||
         (same(c.front(), x1, y1) && same(c.back(), x0, y0));
}

// Every pixel of the chain lies on the drawn line through (x0, y0) along
// (dx, dy), or next to it: the chain did not wander onto the line crossing
// it. (The skeleton walk ends a line's arms on the junction's own pixels,
// which are the crossing line's, one pixel off: so within 1 px, where a
// chain that ran on along the other line would be 2 px off within two
// steps.)
bool on_line(const pr::Chain& c, int x0, int y0, int dx, int dy) {
  const double norm = std::hypot(dx, dy);
  return std::all_of(c.begin(), c.end(), [&](cv::Point2f p) {
    const double ox = p.x - x0, oy = p.y - y0;
    return std::abs(ox * dy - oy * dx) / norm <= 1.0;
  });
}

TEST(LineChains, AStraightLineIsOneChainFromEndToEnd) {
  cv::Mat img = blank();
  draw(img, 10, 20, 1, 0, 39);  // (10, 20) .. (49, 20): 40 pixels
  const auto chains = pr::trace_chains(img, 5);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_EQ(chains[0].size(), 40u);
  EXPECT_TRUE(ends_at(chains[0], 10, 20, 49, 20));
  EXPECT_DOUBLE_EQ(pr::chain_length(chains[0]), 39.0);
}

TEST(LineChains, ChainsShorterThanTheMinimumAreDropped) {
  cv::Mat img = blank();
  draw(img, 10, 10, 1, 0, 3);   // 4 pixels: dropped at a minimum of 5
  draw(img, 10, 30, 1, 0, 4);   // 5 pixels: kept
  draw(img, 10, 50, 1, 1, 20);  // 21 pixels, diagonal: kept
  const auto chains = pr::trace_chains(img, 5);
  ASSERT_EQ(chains.size(), 2u);
  std::vector<std::size_t> sizes{chains[0].size(), chains[1].size()};
  std::sort(sizes.begin(), sizes.end());
  EXPECT_EQ(sizes[0], 5u);
  EXPECT_EQ(sizes[1], 21u);
  // A diagonal step is sqrt(2) long (2e-6 px: each step's length is a
  // float, sqrt(2) to half a float ulp, 6e-8, times 20 steps).
  for (const auto& c : chains) {
    if (c.size() == 21u) {
      EXPECT_NEAR(pr::chain_length(c), 20 * std::sqrt(2.0), 2e-6);
    }
  }
  // With a minimum of 6 the 5-pixel line goes too.
  EXPECT_EQ(pr::trace_chains(img, 6).size(), 1u);
}

TEST(LineChains, ACrossingCutsTheSkeletonAndTheJoinFollowsEachLineThroughIt) {
  cv::Mat img = blank();
  draw(img, 5, 40, 1, 0, 70);  // horizontal (5, 40) .. (75, 40)
  draw(img, 40, 5, 0, 1, 70);  // vertical (40, 5) .. (40, 75)
  const auto traced = pr::trace_chains(img, 5);
  // Cut at the junction: four arms (and no chain crosses it).
  EXPECT_EQ(traced.size(), 4u);
  const auto joined = pr::join_chains(traced, kGapPx, kTurnDeg);
  ASSERT_EQ(joined.size(), 2u);
  int horizontal = 0, vertical = 0;
  for (const auto& c : joined) {
    if (ends_at(c, 5, 40, 75, 40)) {
      ++horizontal;
      EXPECT_TRUE(on_line(c, 5, 40, 1, 0));
    } else if (ends_at(c, 40, 5, 40, 75)) {
      ++vertical;
      EXPECT_TRUE(on_line(c, 40, 5, 0, 1));
    }
    // The junction's own pixels are left out by the skeleton walk: the
    // joined line is its two arms, 70 of its 71 pixels at most.
    EXPECT_GE(pr::chain_length(c), 66.0);
  }
  EXPECT_EQ(horizontal, 1);
  EXPECT_EQ(vertical, 1);
}

TEST(LineChains, ALineIsFollowedThroughAnObliqueCrossing) {
  cv::Mat img = blank();
  draw(img, 5, 40, 1, 0, 70);  // horizontal (5, 40) .. (75, 40)
  draw(img, 8, 8, 1, 1, 64);   // diagonal (8, 8) .. (72, 72), crossing at (40, 40)
  const auto joined = pr::join_chains(pr::trace_chains(img, 5), kGapPx, kTurnDeg);
  ASSERT_EQ(joined.size(), 2u);
  int horizontal = 0, diagonal = 0;
  for (const auto& c : joined) {
    if (ends_at(c, 5, 40, 75, 40)) {
      ++horizontal;
      EXPECT_TRUE(on_line(c, 5, 40, 1, 0));
    } else if (ends_at(c, 8, 8, 72, 72)) {
      ++diagonal;
      EXPECT_TRUE(on_line(c, 8, 8, 1, 1));
    }
  }
  EXPECT_EQ(horizontal, 1);
  EXPECT_EQ(diagonal, 1);
}

TEST(LineChains, AtATheThroughLineIsOneChainAndTheStemAnother) {
  cv::Mat img = blank();
  draw(img, 5, 40, 1, 0, 70);  // the through line (5, 40) .. (75, 40)
  draw(img, 40, 5, 0, 1, 34);  // the stem (40, 5) .. (40, 39), ending on it
  const auto joined = pr::join_chains(pr::trace_chains(img, 5), kGapPx, kTurnDeg);
  ASSERT_EQ(joined.size(), 2u);
  const bool first_through = ends_at(joined[0], 5, 40, 75, 40);
  const pr::Chain& through = first_through ? joined[0] : joined[1];
  const pr::Chain& stem = first_through ? joined[1] : joined[0];
  EXPECT_TRUE(ends_at(through, 5, 40, 75, 40));
  EXPECT_TRUE(on_line(through, 5, 40, 1, 0));
  EXPECT_TRUE(same(stem.front(), 40, 5) || same(stem.back(), 40, 5));
  EXPECT_TRUE(on_line(stem, 40, 5, 0, 1));
}

TEST(LineChains, AGapIsJoinedWhereTheLineRunsOn) {
  cv::Mat img = blank();
  draw(img, 5, 40, 1, 0, 25);   // (5, 40) .. (30, 40)
  draw(img, 35, 40, 1, 0, 40);  // (35, 40) .. (75, 40): a gap of 4 pixels, 5 px end to end
  const auto joined = pr::join_chains(pr::trace_chains(img, 5), kGapPx, kTurnDeg);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_TRUE(ends_at(joined[0], 5, 40, 75, 40));
  EXPECT_EQ(joined[0].size(), 26u + 41u);
}

TEST(LineChains, AGapBeyondThreeTimesTheLimitStaysOpen) {
  cv::Mat img = blank();
  draw(img, 5, 40, 1, 0, 20);   // (5, 40) .. (25, 40)
  draw(img, 42, 40, 1, 0, 33);  // (42, 40) .. (75, 40): 17 px end to end, over 3 x 5
  EXPECT_EQ(pr::join_chains(pr::trace_chains(img, 5), kGapPx, kTurnDeg).size(), 2u);
  // Within three times the limit, in one straight line: joined (the arms of
  // a line whose skeleton merged with a crossing one's over a few pixels).
  cv::Mat near = blank();
  draw(near, 5, 40, 1, 0, 20);   // (5, 40) .. (25, 40)
  draw(near, 38, 40, 1, 0, 37);  // (38, 40) .. (75, 40): 13 px end to end
  const auto joined = pr::join_chains(pr::trace_chains(near, 5), kGapPx, kTurnDeg);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_TRUE(ends_at(joined[0], 5, 40, 75, 40));
}

TEST(LineChains, EndsThatDoNotRunOnAreNotJoined) {
  // A corner: the two lines' ends 3 px apart, but turning 90 deg.
  cv::Mat corner = blank();
  draw(corner, 5, 40, 1, 0, 30);   // (5, 40) .. (35, 40)
  draw(corner, 38, 43, 0, 1, 30);  // (38, 43) .. (38, 73)
  EXPECT_EQ(pr::join_chains(pr::trace_chains(corner, 5), kGapPx, kTurnDeg).size(), 2u);
  // Parallel lines side by side, ends 4 px apart along and 6 px across:
  // the bridge would run at 56 deg to both.
  cv::Mat offset = blank();
  draw(offset, 5, 40, 1, 0, 30);   // (5, 40) .. (35, 40)
  draw(offset, 39, 46, 1, 0, 30);  // (39, 46) .. (69, 46)
  EXPECT_EQ(pr::join_chains(pr::trace_chains(offset, 5), kGapPx, kTurnDeg).size(), 2u);
}

}  // namespace
