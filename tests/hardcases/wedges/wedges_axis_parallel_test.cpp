// A set containing the tunnel's axis (issue 40): axis 35/000 and a set
// 60/125 (striking 035) with the tunnel-wedges sample's other two sets.
// Turned by +-1e-9 and +-1e-6 degrees it gives the wedges of the exact
// case: the same codes, places and volumes, no wedge "could not be built",
// and the face wedge neither comes nor goes with the sign of the turn.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

constexpr double kRad = std::numbers::pi / 180;

WedgeAnalysis with_second_set_turned(double turn_deg) {
  const std::vector<WedgeJointSet> sets{
      {"J1", geometry::plane_normal_deg(65, 20), 32 * kRad, 0},
      {"J2", geometry::plane_normal_deg(60, 125 + turn_deg), 30 * kRad, 0},
      {"J3", geometry::plane_normal_deg(55, 260), 30 * kRad, 0}};
  WedgeOptions o;
  o.density = 2650;
  o.uncertainty = 2 * kRad;
  o.trace_length_limit = 6.0;
  return analyse_wedges(horseshoe_profile(3, 1, 5, -1.5),
                        axis_frame(35 * kRad, 0, Eigen::Vector3d::Zero(), "axis"),
                        Eigen::Vector3d::Zero(), sets, o);
}

const Wedge* find(const WedgeAnalysis& a, const std::string& code) {
  for (const auto& w : a.wedges)
    if (w.code == code) return &w;
  return nullptr;
}

TEST(WedgesAxisParallel, ExactCaseBuildsTheRoofWallsFloorAndFaceWedges) {
  const WedgeAnalysis a = with_second_set_turned(0);
  for (const char* code : {"111", "010", "101", "000", "100"})
    EXPECT_NE(find(a, code), nullptr) << code;
  ASSERT_NE(find(a, "111"), nullptr);
  EXPECT_EQ(find(a, "111")->place, WedgePlace::roof);
  ASSERT_NE(find(a, "100"), nullptr);
  EXPECT_EQ(find(a, "100")->place, WedgePlace::face);
  for (const auto& n : a.none)
    EXPECT_EQ(n.reason.find("could not be built"), std::string::npos) << n.code << ": " << n.reason;
}

TEST(WedgesAxisParallel, TinyTurnsEitherWayGiveTheExactCasesWedges) {
  const WedgeAnalysis exact = with_second_set_turned(0);
  ASSERT_FALSE(exact.wedges.empty());
  for (double turn : {1e-9, -1e-9, 1e-6, -1e-6}) {
    const WedgeAnalysis a = with_second_set_turned(turn);
    ASSERT_EQ(a.wedges.size(), exact.wedges.size()) << turn;
    for (std::size_t i = 0; i < exact.wedges.size(); ++i) {
      const Wedge& e = exact.wedges[i];
      const Wedge& w = a.wedges[i];
      EXPECT_EQ(w.code, e.code) << turn;
      EXPECT_EQ(w.place, e.place) << turn << " " << e.code;
      // A turn of 1e-6 deg (1.7e-8 rad) changes a wedge's size by about
      // that much of itself: 1e-7 relative leaves a factor of 6 (and the
      // set taken as parallel to the axis gives the exact case to rounding).
      EXPECT_NEAR(w.mass.volume, e.mass.volume, 1e-7 * e.mass.volume) << turn << " " << e.code;
      EXPECT_NEAR(w.removable.margin, e.removable.margin, 1e-7) << turn << " " << e.code;
    }
    for (const auto& n : a.none)
      EXPECT_EQ(n.reason.find("could not be built"), std::string::npos)
          << turn << " " << n.code << ": " << n.reason;
  }
}

TEST(WedgesAxisParallel, TurnsBeyondTheToleranceKeepEveryWedgeNearTheExactOne) {
  // 0.01 deg either way: beyond kWedgeAxisParallelRad, so the set is not
  // taken as parallel; the face wedge stays whichever way it turns.
  const WedgeAnalysis exact = with_second_set_turned(0);
  const Eigen::Vector3d along = axis_frame(35 * kRad, 0, Eigen::Vector3d::Zero(), "axis").along;
  for (double turn : {0.01, -0.01}) {
    const WedgeAnalysis a = with_second_set_turned(turn);
    ASSERT_EQ(a.wedges.size(), exact.wedges.size()) << turn;
    for (std::size_t i = 0; i < exact.wedges.size(); ++i) {
      const Wedge& e = exact.wedges[i];
      const Wedge& w = a.wedges[i];
      EXPECT_EQ(w.code, e.code) << turn;
      EXPECT_EQ(w.place, e.place) << turn << " " << e.code;
      // The set's face turns by d = 1.7e-4 rad about a line through the
      // apex: the wedge's far corners move by d times their distance from
      // it, at most the wedge's length L along the axis, so its volume by
      // at most 3 d L / h relative (h its apex height); twice that allows
      // for the other faces' corners that move with them.
      double lo = 1e300, hi = -1e300;
      for (const auto& v : e.block.vertices()) {
        lo = std::min(lo, v.dot(along));
        hi = std::max(hi, v.dot(along));
      }
      const double d = 0.01 * kRad;
      const double tol = 6 * d * std::max(hi - lo, e.apex_height) / e.apex_height;
      EXPECT_NEAR(w.mass.volume, e.mass.volume, tol * e.mass.volume) << turn << " " << e.code;
    }
  }
}

}  // namespace
}  // namespace rockface::tunnel
