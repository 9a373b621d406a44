// The phases of simulate_block_motion (dynamics/block_dynamics_phases.h),
// each on its own: the block's own units, a floor above the block refused,
// the events of a change of contact mode, the bisection that finds the
// earliest event inside a step, the end of free flight, how the motion is
// said to end, and the landing's words.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mechanics/block_loads.h"
#include "core/mechanics/dynamics/block_dynamics_phases.h"
#include "core/mechanics/dynamics/tolerances.h"
#include "tests/core/mechanics/dynamics_support.h"

namespace rockface::mechanics {
namespace {

using namespace testing;
namespace phases = dynamics_phases;

// A block under a roof (as in dynamics_closed_forms_test): three joints
// meet at the origin, up in the rock; its base is the roof z = -2.
blocks::Polyhedron roof_block() {
  using blocks::PlaneKind;
  return bounded("roof",
                 {bounding(0, "J1", PlaneKind::Joint, -normal_deg(50, 0), {0, 0, 0}, {}),
                  bounding(1, "J2", PlaneKind::Joint, -normal_deg(50, 120), {0, 0, 0}, {}),
                  bounding(2, "J3", PlaneKind::Joint, -normal_deg(50, 240), {0, 0, 0}, {}),
                  bounding(3, "R", PlaneKind::FreeFace, normal_deg(0, 0), {0, 0, -2}, {})},
                 {});
}

struct RoofMotion {
  blocks::Polyhedron block = roof_block();
  blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  kinematics::Effects effects = gravity();
  BlockMotion motion{block, mass, block_loads(block, mass, effects), friction_on_joints(block, 30)};
};

TEST(DynamicsPhases, TheBlocksOwnUnitsAreItsSizeAndTheTimeToFallIt) {
  const RoofMotion r;
  const phases::Scales k = phases::block_scales(r.motion);
  EXPECT_EQ(k.length, r.motion.length());
  EXPECT_NEAR(k.time, std::sqrt(k.length / kG), 1e-12);
  EXPECT_NEAR(k.speed * k.time, k.length, 1e-12 * k.length);
  EXPECT_NEAR(k.energy, r.mass.mass * kG * k.length, 1e-9 * k.energy);
  // The state packs and unpacks to the same pose and velocity.
  phases::Physical p;
  p.pose.u = Eigen::Vector3d(0.1, -0.2, 0.3);
  p.velocity.v = Eigen::Vector3d(1, 2, 3);
  p.velocity.w = Eigen::Vector3d(-0.5, 0.25, 0);
  p.work = 1000;
  const phases::Physical q = phases::unpack(phases::pack(p, k), k);
  EXPECT_LT((q.pose.u - p.pose.u).norm(), 1e-12);
  EXPECT_LT((q.velocity.v - p.velocity.v).norm(), 1e-12);
  EXPECT_LT((q.velocity.w - p.velocity.w).norm(), 1e-12);
  EXPECT_NEAR(q.work, p.work, 1e-9);
}

TEST(DynamicsPhases, AFloorAboveTheBlockIsRefusedAndOneBelowKeptWithAUnitNormal) {
  const RoofMotion r;
  const phases::Scales k = phases::block_scales(r.motion);
  std::vector<std::string> notes;
  const auto below = phases::usable_floor(
      DynamicsFloor{Eigen::Vector3d(0, 0, -7), Eigen::Vector3d(0, 0, 2)}, r.motion, k, notes);
  ASSERT_TRUE(below);
  EXPECT_NEAR(below->normal.norm(), 1.0, 1e-15);
  EXPECT_TRUE(notes.empty());
  // A floor at z = -1 lies above the block's base (z = -2).
  const auto cuts = phases::usable_floor(
      DynamicsFloor{Eigen::Vector3d(0, 0, -1), Eigen::Vector3d::UnitZ()}, r.motion, k, notes);
  EXPECT_FALSE(cuts);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_FALSE(phases::usable_floor(std::nullopt, r.motion, k, notes));
}

TEST(DynamicsPhases, AChangeOfContactModeSaysEachPlaneLeftThenTheNewMode) {
  ContactMode two;
  two.kind = ModeKind::Sliding;
  two.planes = {"J1", "J2"};
  ContactMode one = two;
  one.planes = {"J1"};
  std::vector<MotionEvent> events;
  phases::record_mode_change(events, two, one, 0.5);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, "leaves");
  EXPECT_EQ(events[0].what, "leaves J2");
  EXPECT_EQ(events[0].planes, (std::vector<std::string>{"J2"}));
  EXPECT_EQ(events[1].kind, "slides");
  EXPECT_EQ(events[1].what, one.describe());
  EXPECT_EQ(events[1].time, 0.5);
  // Into free fall: the last plane left, then "free_fall".
  events.clear();
  phases::record_mode_change(events, one, ContactMode{}, 1.0);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1].kind, "free_fall");
  // No change: no event.
  events.clear();
  phases::record_mode_change(events, one, one, 1.0);
  EXPECT_TRUE(events.empty());
}

TEST(DynamicsPhases, TheEarliestEventInsideAStepIsFoundByBisection) {
  // The state's first component runs with time; the event is when it
  // passes 0.3 of a step of 1.
  auto advance = [](double h) {
    phases::State s{};
    s[0] = h;
    return s;
  };
  auto happened = [](const phases::State& s) { return s[0] >= 0.3; };
  const phases::EventTime e = phases::locate_event(advance(1.0), 1.0, advance, happened);
  EXPECT_GE(e.after, 0.3);
  EXPECT_LT(e.after - 0.3, 2 * kEventTimeRel);
  EXPECT_EQ(e.state[0], e.after);  // the state at that time, not the step's end
}

TEST(DynamicsPhases, FreeFlightGoesOnAtMostAMinuteBeyondNowAndTheDuration) {
  phases::Scales k;
  k.time = 0.5;  // 60 s = 120 T
  EXPECT_DOUBLE_EQ(phases::flight_end(1.0, 4.0, k), 121.0);
  EXPECT_DOUBLE_EQ(phases::flight_end(10.0, 4.0, k), 124.0);
}

TEST(DynamicsPhases, TheOutcomeSaysHowTheMotionEnded) {
  ContactMode rest;
  rest.kind = ModeKind::Rest;
  ContactMode sliding;
  sliding.kind = ModeKind::Sliding;
  EXPECT_EQ(phases::outcome_of(true, ContactMode{}, phases::FloorGiven::usable), "lands");
  EXPECT_EQ(phases::outcome_of(false, rest, phases::FloorGiven::none), "at rest");
  EXPECT_EQ(phases::outcome_of(false, ContactMode{}, phases::FloorGiven::usable),
            "in free flight when the time ran out");
  EXPECT_EQ(phases::outcome_of(false, ContactMode{}, phases::FloorGiven::none),
            "in free flight (no floor given)");
  EXPECT_EQ(phases::outcome_of(false, sliding, phases::FloorGiven::none), "moving at the end");
}

TEST(DynamicsPhases, TheLandingIsSaidFromTheFaceItLeftThroughOrFromItsStart) {
  Landing l;
  l.speed = 7.14;
  l.distance_from_start = 2.0;
  EXPECT_EQ(phases::landing_text(l), "lands 2.0 m from where it started at 7.1 m/s");
  l.face = "F1";
  l.distance_from_face = 3.25;
  EXPECT_EQ(phases::landing_text(l), "lands 3.2 m from the face F1 at 7.1 m/s");
  // Issue 39: from the face's foot, out and down, not from its plane
  // extended ("lands -14.8 m from the face" for a block in front of it).
  l.distance_from_foot = 12.34;
  l.drop_below_foot = 14.82;
  EXPECT_EQ(phases::landing_text(l),
            "lands 12.3 m out from the foot of the face F1, 14.8 m below it, at 7.1 m/s");
  l.distance_from_foot = -0.51;
  l.drop_below_foot = -0.25;
  EXPECT_EQ(phases::landing_text(l),
            "lands 0.5 m behind the foot of the face F1, 0.2 m above it, at 7.1 m/s");
}

// The slope wedge of tools/samples/slope-wedge.scene.json: two joints under
// a 70/180 face (the rock north of it, below it) and a flat top at z = 3.
blocks::Polyhedron slope_wedge() {
  using blocks::PlaneKind;
  return bounded("wedge",
                 {bounding(0, "J1", PlaneKind::Joint, normal_deg(45, 105), {5, 5, 2}, {}),
                  bounding(1, "J2", PlaneKind::Joint, normal_deg(50, 235), {5, 5, 2}, {}),
                  bounding(2, "F1", PlaneKind::FreeFace, -normal_deg(70, 180), {5, 0, 0}, {}),
                  bounding(3, "F2", PlaneKind::FreeFace, -normal_deg(0, 0), {5, 5, 3}, {})},
                 {});
}

TEST(DynamicsPhases, ALandingFarBelowIsSaidOutFromTheFacesFootAndDown) {
  const blocks::Polyhedron block = slope_wedge();
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  const kinematics::Effects effects = gravity();
  const BlockMotion motion{block, mass, block_loads(block, mass, effects),
                           friction_on_joints(block, 30)};
  // It left southwards (out of the face), 10 m, and fell until its lowest
  // corner touched a floor at z = -30.
  double lowest = 1e9;
  for (const auto& v : block.vertices()) lowest = std::min(lowest, v.z());
  phases::Physical last;
  last.pose.u = Eigen::Vector3d(0.5, -10, -30 - lowest);
  last.velocity.v = Eigen::Vector3d(0, -3, -20);
  const DynamicsFloor floor{Eigen::Vector3d(0, 0, -30), Eigen::Vector3d::UnitZ()};
  const Landing l = phases::landing_of(block, motion, last, floor, 2.5);
  ASSERT_EQ(l.face, "F1");
  ASSERT_TRUE(l.distance_from_foot && l.drop_below_foot);
  // The foot: the lowest corner of the wedge's face on F1, found here from
  // the plane's equation (1e-9 m: the corners are intersections of planes).
  const Eigen::Vector3d n = normal_deg(70, 180);
  Eigen::Vector3d foot(0, 0, 1e9);
  for (const auto& v : block.vertices())
    if (std::abs(n.dot(v - Eigen::Vector3d(5, 0, 0))) < 1e-9 && v.z() < foot.z()) foot = v;
  ASSERT_LT(foot.z(), 3);
  // Out of the face is south (its dip direction, 180): minus y. Exact
  // arithmetic on the same numbers but for rounding (1e-9 m).
  EXPECT_NEAR(*l.distance_from_foot, -(l.centroid.y() - foot.y()), 1e-9);
  EXPECT_GT(*l.distance_from_foot, 0);  // 10 m south of where it was: out past the foot
  EXPECT_NEAR(*l.drop_below_foot, foot.z() - l.point.z(), 1e-9);
  EXPECT_NEAR(l.point.z(), -30, 1e-9);  // the touching corner, on the floor (rounding only)
  // The face's plane, extended down to the floor 30 m below, lies 30 / tan
  // 70 = 10.9 m further out than its foot: from the plane the block is
  // "behind the face" though it lies in front of its foot.
  ASSERT_TRUE(l.distance_from_face);
  EXPECT_LT(*l.distance_from_face, *l.distance_from_foot);
}

TEST(DynamicsPhases, ABlockLandingStraightBelowIsAtNoDistanceFromItsStart) {
  const RoofMotion r;
  const DynamicsFloor floor{Eigen::Vector3d(0, 0, -7), Eigen::Vector3d::UnitZ()};
  phases::Physical last;
  last.pose.u = Eigen::Vector3d(0, 0, -5);
  last.velocity.v = Eigen::Vector3d(0, 0, -9.9);
  const Landing l = phases::landing_of(r.block, r.motion, last, floor, 1.0);
  EXPECT_EQ(l.time, 1.0);
  EXPECT_NEAR(l.point.z(), -7.0, 1e-9);  // a corner of its base, 5 m lower
  EXPECT_NEAR(l.speed, 9.9, 1e-12);
  EXPECT_EQ(l.distance_from_start, 0.0);
  EXPECT_FALSE(l.distance_from_face);  // the roof is its only free face, and flat
  EXPECT_NEAR(l.kinetic_translational, 0.5 * r.mass.mass * 9.9 * 9.9, 1e-9 * r.mass.mass);
}

}  // namespace
}  // namespace rockface::mechanics
