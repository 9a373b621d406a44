// The phases of analyse_wedges (wedge_analysis_phases.h), each on its own:
// the sets refused by name, a pyramid's planes and code, three sets through
// one line refused, the face's pyramid, the roof wedge of one pyramid in a
// square section (and none of a face wedge when the face is not asked
// for), the apex bisection to a trace-length limit, and the order.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "core/common/error.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/tunnel/wedge_analysis_phases.h"
#include "core/tunnel/wedge_section.h"

namespace rockface::tunnel {
namespace {

namespace phases = wedge_phases;
constexpr double kRad = std::numbers::pi / 180.0;

// Three sets dipping 60 toward 0, 120 and 240 degrees.
std::vector<WedgeJointSet> symmetric_sets() {
  std::vector<WedgeJointSet> s;
  for (int i = 0; i < 3; ++i)
    s.push_back(
        {"J" + std::to_string(i + 1), geometry::plane_normal_deg(60, 120.0 * i), 30 * kRad, 0});
  return s;
}

TunnelFrame north_axis() {
  return axis_frame(0, 0, Eigen::Vector3d::Zero(), "axis");
}

TEST(WedgePhases, TooFewSetsOrOneWithoutOrientationAreRefusedByName) {
  auto sets = symmetric_sets();
  EXPECT_NO_THROW(phases::check_sets(sets));
  sets[1].normal = Eigen::Vector3d::Zero();
  try {
    phases::check_sets(sets);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sets[1]"), std::string::npos) << e.what();
  }
  sets.pop_back();
  EXPECT_THROW(phases::check_sets(sets), InputError);
}

TEST(WedgePhases, APyramidHasItsSetsOnTheSidesOfItsCode) {
  const auto sets = symmetric_sets();
  // Combination 5 = 0b101: lower, upper, lower.
  const phases::SetPyramid p = phases::set_pyramid(sets, {0, 1, 2}, 5);
  EXPECT_EQ(p.code, "101");
  EXPECT_EQ(p.ids, (std::vector<std::string>{"J1", "J2", "J3"}));
  ASSERT_EQ(p.inward.size(), 3u);
  EXPECT_LT((p.inward[0] + sets[0].normal.normalized()).norm(), 1e-15);
  EXPECT_LT((p.inward[1] - sets[1].normal.normalized()).norm(), 1e-15);
  EXPECT_EQ(phases::code_text(5, {1, 3}, {1, -1}), "20212");
}

TEST(WedgePhases, ThreeSetsThroughOneLineBoundNoWedge) {
  auto sets = symmetric_sets();
  EXPECT_FALSE(phases::parallel_sets(sets, {0, 1, 2}, 1 * kRad));
  // Three vertical sets all contain the vertical line.
  for (int i = 0; i < 3; ++i) sets[i].normal = geometry::plane_normal_deg(90, 50.0 * i);
  const auto none = phases::parallel_sets(sets, {0, 1, 2}, 1 * kRad);
  ASSERT_TRUE(none);
  EXPECT_EQ(none->code, "***");
  EXPECT_NE(none->reason.find("meet in one line"), std::string::npos);
}

TEST(WedgePhases, TheFacesPyramidHoldsTheRockAheadOfIt) {
  const geometry::Cone ep = phases::face_excavation_pyramid(north_axis());
  // North is ahead: inside the rock; south, back into the tunnel: outside.
  EXPECT_GT(ep.margin_of(Eigen::Vector3d::UnitY()), 0);
  EXPECT_LT(ep.margin_of(-Eigen::Vector3d::UnitY()), 0);
}

kinematics::Effects gravity() {
  kinematics::Effects e;
  e.push_back(std::make_unique<kinematics::GravityEffect>(Eigen::Vector3d(0, 0, -9.81)));
  return e;
}

struct Square {
  std::vector<WedgeJointSet> sets = symmetric_sets();
  TunnelFrame frame = north_axis();
  DesignProfile profile = rectangle_profile(6, 6, 0);
  SectionPolygon section = section_polygon(profile, 0.002, "profile");
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  WedgeOptions options;
  kinematics::Effects loads = gravity();
  phases::Context context() const {
    return {section, frame, datum, sets, options, loads, profile.ray_centre()};
  }
};

TEST(WedgePhases, TheRoofPyramidOfASquareSectionGivesTheClosedFormTetrahedron) {
  const Square s;
  // Below all three sets (code 111): a regular-based tetrahedron apex up,
  // its base spanning the 6 m roof.
  const phases::SetPyramid p = phases::set_pyramid(s.sets, {0, 1, 2}, 7);
  ASSERT_EQ(p.code, "111");
  const geometry::Cone jp(p.inward);
  const double margin = jp.margin().angle;
  ASSERT_GT(margin, 0);
  const phases::FoundWedge found =
      phases::perimeter_wedge(s.context(), p, jp.edges(margin), margin);
  ASSERT_TRUE(found.wedge);
  EXPECT_FALSE(found.none);
  const Wedge& w = *found.wedge;
  EXPECT_EQ(w.place, WedgePlace::roof);
  const double r = 6 / (2 * std::sqrt(3.0)), h = r * std::tan(60 * kRad);
  EXPECT_NEAR(w.apex_height, h, 1e-9 * h);
  EXPECT_NEAR(w.mass.volume, std::sqrt(3.0) * r * r * r * std::tan(60 * kRad), 1e-9 * h * h * h);
  EXPECT_NEAR(w.position_deg, 90, 1e-9);
  EXPECT_LT((w.outline.front() - Eigen::Vector2d(w.apex.x(), w.apex.z())).norm(), 1e-12);
  ASSERT_TRUE(w.mode);
  EXPECT_EQ(w.mode->type, kinematics::ModeType::Falling);
  EXPECT_FALSE(w.segments.empty());
}

TEST(WedgePhases, NoFaceWedgeWhenTheFaceIsNotAskedFor) {
  Square s;
  s.options.face = false;
  const phases::SetPyramid p = phases::set_pyramid(s.sets, {0, 1, 2}, 7);
  const geometry::Cone jp(p.inward);
  const phases::FoundWedge f = phases::face_wedge(s.context(), p, jp.edges(jp.margin().angle),
                                                  phases::face_excavation_pyramid(s.frame));
  EXPECT_FALSE(f.wedge);
  EXPECT_FALSE(f.none);
}

TEST(WedgePhases, TheApexIsMovedInUntilTheLongestTraceIsTheLimit) {
  const Square s;
  // A base on the roof (v = 6) from u = -3 to 3; the largest apex 5 m above
  // its middle; a longest trace that grows with the apex's height above
  // the roof, twice it.
  const std::vector<BasePiece> base = {{{-3, 6}, {3, 6}, 0}};
  const Eigen::Vector2d q_max(0, 11);
  const Eigen::Vector2d q = phases::apex_at_trace_limit(
      s.section, base, q_max, 4.0, [](const Eigen::Vector2d& at) { return 2 * (at.y() - 6); });
  EXPECT_NEAR(q.x(), 0, 1e-12);
  EXPECT_NEAR(q.y(), 8, 1e-5);  // a trace of 4 m
  EXPECT_LE(2 * (q.y() - 6), 4.0);
}

TEST(WedgePhases, WedgesAreOrderedByPlaceThenByFallingVolume) {
  std::vector<Wedge> w(4);
  w[0].place = WedgePlace::face;
  w[0].mass.volume = 9;
  w[1].place = WedgePlace::roof;
  w[1].mass.volume = 1;
  w[2].place = WedgePlace::left_wall;
  w[2].mass.volume = 5;
  w[3].place = WedgePlace::roof;
  w[3].mass.volume = 2;
  phases::order_wedges(w);
  EXPECT_EQ(w[0].mass.volume, 2);
  EXPECT_EQ(w[1].mass.volume, 1);
  EXPECT_EQ(w[2].place, WedgePlace::left_wall);
  EXPECT_EQ(w[3].place, WedgePlace::face);
}

}  // namespace
}  // namespace rockface::tunnel
