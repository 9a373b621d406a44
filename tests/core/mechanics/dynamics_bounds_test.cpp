// Issue 41: the motion after failure always ends, and says how. A step
// budget (evaluations of the equations of motion, free of the wall clock)
// and an event limit stop an integration that cannot reach its end, with
// the reason in `stopped`; more steps than kMaxDynamicsStepsAsked asked
// for (duration_s / max_step_s) are refused by name; a floor above the
// block is said as such, not as "no floor given".
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/mechanics/dynamics/block_dynamics.h"
#include "core/mechanics/dynamics/tolerances.h"
#include "tests/core/mechanics/dynamics_support.h"
#include "tests/support/refusal.h"

namespace rockface::mechanics {
namespace {

using namespace testing;
using rockface::test::refusal;

// A block under a roof: three joints meet at the origin, up in the rock;
// its base is the roof z = -2. It falls out freely.
blocks::Polyhedron roof_block() {
  using blocks::PlaneKind;
  return bounded("roof",
                 {bounding(0, "J1", PlaneKind::Joint, -normal_deg(50, 0), {0, 0, 0}, {}),
                  bounding(1, "J2", PlaneKind::Joint, -normal_deg(50, 120), {0, 0, 0}, {}),
                  bounding(2, "J3", PlaneKind::Joint, -normal_deg(50, 240), {0, 0, 0}, {}),
                  bounding(3, "R", PlaneKind::FreeFace, normal_deg(0, 0), {0, 0, -2}, {})},
                 {});
}

TEST(DynamicsBounds, AFloorAboveTheBlockIsSaidNotTakenForNoFloor) {
  DynamicsOptions o = options(0.5, 0.1);
  o.floor = DynamicsFloor{Eigen::Vector3d(0, 0, -1), Eigen::Vector3d::UnitZ()};
  const BlockDynamics d = run(roof_block(), 30, gravity(), o);
  EXPECT_EQ(d.outcome,
            "in free flight (the floor given lies above the block: no landing computed)");
  EXPECT_TRUE(d.stopped.empty());
}

TEST(DynamicsBounds, TheStepBudgetStopsTheIntegrationAndSaysWhy) {
  DynamicsOptions o = options(2.0, 0.1);
  o.max_evaluations = 200;
  const BlockDynamics d = run(roof_block(), 30, gravity(), o);
  EXPECT_EQ(d.outcome, "stopped before the end of the duration");
  EXPECT_EQ(d.stopped.substr(0, 64),
            "the step budget (200 evaluations of the equations of motion) ran");
  EXPECT_LT(d.end_time, 2.0);
  EXPECT_GE(d.evaluations, 200);
  // The same motion without the budget runs to its end.
  const BlockDynamics full = run(roof_block(), 30, gravity(), options(2.0, 0.1));
  EXPECT_TRUE(full.stopped.empty());
  EXPECT_EQ(full.outcome, "in free flight (no floor given)");
}

TEST(DynamicsBounds, TheEventLimitStopsTheIntegrationAndSaysWhy) {
  DynamicsOptions o = options(2.0, 0.1);
  o.max_events = 1;  // the first event (free fall at t = 0) reaches it
  const BlockDynamics d = run(roof_block(), 30, gravity(), o);
  EXPECT_EQ(d.stopped.substr(0, 42), "the event limit (1 events) was reached at ");
  EXPECT_EQ(d.outcome, "stopped before the end of the duration");
}

TEST(DynamicsBounds, TheStepFloorStopsTheIntegrationAndSaysWhy) {
  // Tolerances no step can meet (the scene holds them to 1e-15 / 1e-14;
  // the core takes any positive value): every step is rejected and halved
  // until it falls below the floor. It threw, and the analysis lost every
  // block's report.
  DynamicsOptions o = options(2.0, 0.1);
  o.abs_tol = 1e-300;
  o.rel_tol = 1e-300;
  const BlockDynamics d = run(roof_block(), 30, gravity(), o);
  EXPECT_EQ(d.outcome, "stopped before the end of the duration");
  EXPECT_EQ(d.stopped.substr(0, 62),
            "the step size fell below the step floor (1e-14 of the block's ");
  EXPECT_LT(d.end_time, 2.0);
  // Far inside the budget: the floor, not the budget, stopped it.
  EXPECT_LT(d.evaluations, kDynamicsEvaluationBudget);
}

TEST(DynamicsBounds, MoreStepsThanTheBoundAskedForAreRefusedByName) {
  // 600 s in steps of at most 1 us: 6e8 steps, hours of integration.
  DynamicsOptions o = options(600, 1);
  o.max_step = 1e-6;
  EXPECT_EQ(refusal([&] { run(roof_block(), 30, gravity(), o); }),
            "analysis.dynamics.max_step_s: 1e-06 s over duration_s 600 s is 6e+08 steps; at most "
            "200000 are integrated (a longer max_step_s or a shorter duration_s)");
  // The precise preset over the longest duration is within the bound.
  DynamicsOptions precise = dynamics_options(Preset::precise);
  EXPECT_LE(600 / precise.max_step, kMaxDynamicsStepsAsked);
}

}  // namespace
}  // namespace rockface::mechanics
