// The block's motion after failure: switches between contact modes, the
// same motion in survey coordinates and in a turned scene, and the
// constraint drift over a whole run.
//
// Tolerances: as in dynamics_closed_forms_test.cpp, the integration is
// good to ~1e-7 of the block's size; events are located by bisection to
// 1e-9 of the block's time scale T = sqrt(L / g) (~1 s for these blocks).
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/units.h"
#include "core/mechanics/dynamics/block_diameter.h"
#include "tests/core/mechanics/dynamics_support.h"

namespace rockface::mechanics {
namespace {

using namespace testing;

// A slab sliding down its joint reaches the joint's lower edge (the free
// face "down"): while it translates, its normal force is shifted downhill
// of the centroid by e = mu t / 2 (the friction, acting t / 2 below the
// centroid, must be balanced), so it starts to tip over the rock's edge
// when its centroid is e short of the edge: after d* = a / 2 - mu t / 2.
TEST(BlockDynamicsSwitches, SlabTipsOverTheEdgeOfItsJointThenFallsFreely) {
  const Slab slab;
  const blocks::Polyhedron block = slab.block();
  const double phi = 20, mu = std::tan(deg_to_rad(phi)), alpha = deg_to_rad(slab.psi);
  DynamicsOptions o = options(2.5, 0.1);
  o.floor = DynamicsFloor{Eigen::Vector3d(0, 0, -20), Eigen::Vector3d::UnitZ()};
  const BlockDynamics d = run(block, phi, gravity(), o);
  const double acc = kG * (std::sin(alpha) - mu * std::cos(alpha));
  const double tip = std::sqrt(2 * (slab.a / 2 - mu * slab.t / 2) / acc);
  const MotionEvent* turns = find_event(d, "rotates");
  ASSERT_NE(turns, nullptr);
  EXPECT_EQ(turns->what, "rotates about edge J1-down");
  // Bisection to 1e-9 T, on a motion integrated to ~1e-7: 1e-6 s.
  EXPECT_NEAR(turns->time, tip, 1e-6);
  // Then it leaves J1 and falls freely: a parabola and a constant
  // angular momentum from the moment it leaves.
  const MotionEvent* falls = find_event(d, "free_fall");
  ASSERT_NE(falls, nullptr);
  EXPECT_GT(falls->time, tip);
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  const MotionSample* first = nullptr;
  for (const MotionSample& s : d.samples) {
    if (s.time < falls->time) continue;
    if (!first) {
      first = &s;
      continue;
    }
    const double t = s.time - first->time;
    const Eigen::Vector3d x =
        first->centroid + first->velocity * t + 0.5 * Eigen::Vector3d(0, 0, -kG) * t * t;
    EXPECT_NEAR((s.centroid - x).norm(), 0, 1e-6 * block.size()) << s.time;
    auto momentum = [&](const MotionSample& m) {
      const Eigen::Matrix3d r = m.orientation.toRotationMatrix();
      return Eigen::Vector3d(r * mass.inertia * r.transpose() * m.angular_velocity);
    };
    EXPECT_NEAR((momentum(s) - momentum(*first)).norm(), 0,
                1e-6 * momentum(*first).norm() + 1e-9 * mass.mass * block.size());
  }
  ASSERT_NE(first, nullptr);
  ASSERT_TRUE(d.landing);
  EXPECT_NEAR(d.landing->point.z(), -20, 1e-6);  // the corner that lands is on the floor
  EXPECT_LE(d.drift_after, d.drift_bound);
}

// The same slab run in its own place, at survey coordinates (a datum of
// 10^6 m) and with the whole scene turned (and gravity with it): the
// motion relative to the slab's own frame is the same.
TEST(BlockDynamicsSwitches, SameMotionInSurveyCoordinatesAndInATurnedScene) {
  const Slab slab;
  const double phi = 20;
  const BlockDynamics here = run(slab.block(), phi, gravity(), options(1.5, 0.1));
  Placement survey;
  survey.shift = Eigen::Vector3d(512340.0, 5211870.0, 410.0);
  survey.datum = Eigen::Vector3d(512000.0, 5211000.0, 400.0);
  Placement turned;
  turned.rotation =
      (Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.5, 0.8).normalized())).toRotationMatrix();
  turned.shift = Eigen::Vector3d(1.0e6, -2.0e6, 350.0);
  turned.datum = turned.shift;
  for (const Placement& at : {survey, turned}) {
    const BlockDynamics moved = run(slab.block(at), phi, gravity(at), options(1.5, 0.1));
    ASSERT_EQ(moved.samples.size(), here.samples.size());
    for (size_t i = 0; i < here.samples.size(); ++i) {
      const Eigen::Vector3d u0 = here.samples[i].centroid - here.samples[0].centroid;
      const Eigen::Vector3d u1 = moved.samples[i].centroid - moved.samples[0].centroid;
      // Datum-relative coordinates: only the integration's own error
      // (~1e-7 L) separates the runs, not the 10^6 m.
      EXPECT_NEAR((at.vector(u0) - u1).norm(), 0, 1e-6 * slab.block().size()) << i;
      EXPECT_NEAR((at.vector(here.samples[i].velocity) - moved.samples[i].velocity).norm(), 0,
                  1e-6 * std::sqrt(kG * slab.block().size()));
    }
    ASSERT_EQ(moved.events.size(), here.events.size());
    for (size_t i = 0; i < here.events.size(); ++i) {
      EXPECT_EQ(moved.events[i].what, here.events[i].what);
      EXPECT_NEAR(moved.events[i].time, here.events[i].time, 1e-6);
    }
  }
}

// Over a whole run with sliding, tipping and a fall the contacts that
// carry load never drift from their planes by more than the bound, and
// the rotation stays a unit quaternion.
TEST(BlockDynamicsSwitches, ConstraintDriftStaysWithinItsBound) {
  for (Preset preset : {Preset::fast, Preset::standard, Preset::precise}) {
    const Slab slab;
    DynamicsOptions o = dynamics_options(preset);
    o.duration = 2.0;
    o.sample = 0.1;
    const BlockDynamics d = run(slab.block(), 20, gravity(), o);
    // 1e-9 of the block's diameter (its size in every frame, issue 40).
    EXPECT_DOUBLE_EQ(d.drift_bound, 1e-9 * block_diameter(slab.block()));
    EXPECT_LE(d.drift_after, d.drift_bound) << preset_name(preset);
    // Before projection the drift is the integration's: within its tolerances.
    EXPECT_LE(d.drift_before, 100 * (o.abs_tol + o.rel_tol) * slab.block().size())
        << preset_name(preset);
    EXPECT_LT(d.quaternion_error, 1e-9) << preset_name(preset);  // renormalised every step
  }
}

TEST(BlockDynamicsSwitches, BadOptionsAreNamed) {
  const Slab slab;
  DynamicsOptions o = options(0, 0.1);
  try {
    run(slab.block(), 20, gravity(), o);
    FAIL() << "a zero duration was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "analysis.dynamics.duration_s");
  }
}

}  // namespace
}  // namespace rockface::mechanics
