// A set turned about the tunnel's axis through the whole range from
// rounding to a degree (issue 40): axis 35/000, a set 60/125 that contains
// it, turned by 1e-12 to 1 degree either way on a log grid. The wedges are
// a continuous function of the turn: every wedge of the exact case is
// there with its code and place, its volume and margin moved in proportion
// to the turn; a wedge the exact case does not have is an honest marginal
// one; nothing "could not be built". (Within 1e-6 rad the set is taken as
// containing the axis; there the pyramids with a face on it span 180
// degrees to rounding, and one that came out 2e-16 rad narrower was taken
// as pointed, its apex sent to infinity and its pieces "not a bounded
// solid".)
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

constexpr double kRad = std::numbers::pi / 180;

std::vector<WedgeJointSet> sets_turned(double turn_deg) {
  return {{"J1", geometry::plane_normal_deg(65, 20), 32 * kRad, 0},
          {"J2", geometry::plane_normal_deg(60, 125 + turn_deg), 30 * kRad, 0},
          {"J3", geometry::plane_normal_deg(55, 260), 30 * kRad, 0}};
}

TunnelFrame drive() {
  return axis_frame(35 * kRad, 0, Eigen::Vector3d::Zero(), "axis");
}

WedgeAnalysis wedges_turned(double turn_deg) {
  WedgeOptions o;
  o.density = 2650;
  o.uncertainty = 2 * kRad;
  o.trace_length_limit = 6.0;
  return analyse_wedges(horseshoe_profile(3, 1, 5, -1.5), drive(), Eigen::Vector3d::Zero(),
                        sets_turned(turn_deg), o);
}

const Wedge* find(const WedgeAnalysis& a, const std::string& code) {
  for (const auto& w : a.wedges)
    if (w.code == code) return &w;
  return nullptr;
}

// The turns: 5 per decade from 1e-12 to 1 degree, both signs.
std::vector<double> turns() {
  std::vector<double> out;
  for (int k = -60; k <= 0; ++k)
    for (double sign : {1.0, -1.0}) out.push_back(sign * std::pow(10.0, k / 5.0));
  return out;
}

TEST(WedgesAxisTurnSweep, TheExactCasesWedgesMoveInProportionToTheTurn) {
  const WedgeAnalysis exact = wedges_turned(0);
  ASSERT_EQ(exact.wedges.size(), 5u);
  // The smallest angle between two of the sets' planes: a pyramid edge is
  // the meeting line of two of them, and a turn d of one plane turns that
  // line by at most d / sin(angle).
  const auto sets = sets_turned(0);
  double least_sine = 1;
  for (std::size_t i = 0; i < sets.size(); ++i)
    for (std::size_t j = i + 1; j < sets.size(); ++j)
      least_sine = std::min(least_sine, sets[i].normal.cross(sets[j].normal).norm());
  const Eigen::Vector3d along = drive().along;
  for (double turn : turns()) {
    SCOPED_TRACE("turn " + std::to_string(turn) + " deg");
    const WedgeAnalysis a = wedges_turned(turn);
    const double d = std::abs(turn) * kRad;
    for (const auto& n : a.none)
      EXPECT_EQ(n.reason.find("could not be built"), std::string::npos)
          << n.code << ": " << n.reason;
    for (const Wedge& e : exact.wedges) {
      const Wedge* w = find(a, e.code);
      ASSERT_NE(w, nullptr) << e.code;
      EXPECT_EQ(w->place, e.place) << e.code;
      // The margin is an angle between pyramid edges and a cone: it moves
      // by at most the edges' turn, d / least_sine, plus the 1e-6 rad by
      // which a set that close is taken as containing the axis.
      EXPECT_NEAR(w->removable.margin, e.removable.margin, d / least_sine + 1e-6) << e.code;
      // The set's face turns about a line through the apex by at most
      // d / least_sine: the far corners move by that times their distance
      // from the apex, at most the wedge's length L along the axis or its
      // apex height h, so the volume by at most 3 (d / least_sine) L / h
      // relative; twice that for the other faces' corners that move with
      // them, plus 1e-6 for the snap to the axis within 1e-6 rad.
      double lo = 1e300, hi = -1e300;
      for (const auto& v : e.block.vertices()) {
        lo = std::min(lo, v.dot(along));
        hi = std::max(hi, v.dot(along));
      }
      const double rel =
          6 * (d / least_sine) * std::max(hi - lo, e.apex_height) / e.apex_height + 1e-6;
      EXPECT_NEAR(w->mass.volume, e.mass.volume, rel * e.mass.volume) << e.code;
    }
    // A wedge the exact case does not have opens with the turn: it starts
    // with no size, so it must be flagged marginal.
    for (const Wedge& w : a.wedges) {
      if (find(exact, w.code)) continue;
      EXPECT_TRUE(w.removable.marginal) << w.code << " (" << w.mass.volume << " m3, margin "
                                        << w.removable.margin / kRad << " deg)";
    }
  }
}

}  // namespace
}  // namespace rockface::tunnel
