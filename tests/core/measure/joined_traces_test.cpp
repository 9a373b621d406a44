// Pieces of one trace measured on two pairs' 3D images, joined into one
// trace (core/measure/joined_traces.h): its length over both, and its
// censoring from its own ends, not from where one piece hands over to the
// next at the edge of its photograph.
#include <array>
#include <string>

#include <gtest/gtest.h>

#include "core/measure/joined_traces.h"
#include "core/measure/pair_photo.h"
#include "core/photogrammetry/surface/trace_pieces.h"

namespace rockface::measure {
namespace {

using Eigen::Vector3d;

// A straight piece of joint J1 from `from` to `to`, sampled every 1 cm,
// tapped in `photo`.
MeasuredTrace piece(const std::string& id, const std::string& photo, const Vector3d& from,
                    const Vector3d& to, std::array<bool, 2> censored_ends) {
  MeasuredTrace t;
  t.joint = "J1";
  t.m.id = id;
  t.m.picks = {{photo, Eigen::Vector2d(100, 100)}};
  const int n = static_cast<int>((to - from).norm() / 0.01);
  for (int k = 0; k <= n; ++k) t.m.points.push_back(from + (to - from) * k / n);
  t.m.length = (to - from).norm();
  t.m.censored_ends = censored_ends;
  t.m.censored = censored_ends[0] || censored_ends[1];
  return t;
}

std::vector<JoinedTrace> join(const MeasuredPicks& m) {
  return joined_traces(photogrammetry::join_trace_pieces(trace_pieces(m)), m, {});
}

// W1 leaves pair 1's photograph at x = 1.2 m (censored there), P2 enters
// pair 2's at x = 0.8 m (censored there), 5 mm apart across the overlap
// (a registration residual); both outer ends are inside the mapped area.
MeasuredPicks crossing_trace(bool far_end_censored) {
  MeasuredPicks m;
  m.traces.push_back(piece("W1", "left", Vector3d(0, 0, 0), Vector3d(1.2, 0, 0), {false, true}));
  m.traces.push_back(piece("P2", pair_photo(2, "left"), Vector3d(0.8, 0, 0.005),
                           Vector3d(2.0, 0, 0.005), {true, far_end_censored}));
  return m;
}

TEST(JoinedTraces, TheHandOverBetweenPhotographsIsNoEndOfTheTrace) {
  const auto joined = join(crossing_trace(false));
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].face.pieces, (std::vector<std::string>{"W1", "P2"}));
  EXPECT_FALSE(joined[0].censored) << "each piece is censored only where the other goes on";
  // 0 to 2.0 m along x, counted in 5 cm steps: the 5 mm offset across the
  // overlap adds < 1 mm; the last step may be short, never long.
  EXPECT_NEAR(joined[0].length, 2.0, 0.01);
}

TEST(JoinedTraces, AnOuterEndAtTheEdgeCensorsTheJoinedTrace) {
  const auto joined = join(crossing_trace(true));
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_TRUE(joined[0].censored);
}

TEST(JoinedTraces, PiecesInOnePhotographStayApart) {
  MeasuredPicks m = crossing_trace(false);
  m.traces[1].m.picks[0].photo = "left";
  EXPECT_TRUE(join(m).empty());
}

}  // namespace
}  // namespace rockface::measure
