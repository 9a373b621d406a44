// The sizes the motion is measured by do not depend on the frame (issue 40,
// "motion after failure"): the same block turned by 37 degrees about an
// arbitrary axis has the same drift bound, the same units of integration,
// and so the same motion relative to its own frame.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/mechanics/block_loads.h"
#include "core/mechanics/dynamics/block_dynamics_phases.h"
#include "core/mechanics/dynamics/tolerances.h"
#include "tests/core/mechanics/dynamics_support.h"

namespace rockface::mechanics {
namespace {

using namespace testing;

Placement turned_37_degrees() {
  Placement at;
  at.rotation =
      Eigen::AngleAxisd(37.0 * M_PI / 180.0, Eigen::Vector3d(0.36, -0.8, 0.48).normalized())
          .toRotationMatrix();
  return at;
}

// The largest distance between two corners of the block.
double diameter(const blocks::Polyhedron& p) {
  double d = 0;
  for (const Eigen::Vector3d& a : p.vertices())
    for (const Eigen::Vector3d& b : p.vertices()) d = std::max(d, (a - b).norm());
  return d;
}

TEST(MotionFrame, TheDriftBoundDoesNotDependOnTheFrame) {
  const Placement at = turned_37_degrees();
  const Slab slab;
  for (const auto& [name, here, turned] : {std::make_tuple("wedge", wedge(), wedge(at)),
                                           std::make_tuple("slab", slab.block(), slab.block(at))}) {
    SCOPED_TRACE(name);
    // The same block: the turn moves its corners, not their distances
    // (rounding of the half-space intersection: ~1e-15 of its size).
    ASSERT_NEAR(diameter(turned), diameter(here), 1e-12 * diameter(here));
    const BlockDynamics a = run(here, 30, gravity(), options(0.1, 0.1));
    const BlockDynamics b = run(turned, 30, gravity(at), options(0.1, 0.1));
    // The bound is kDriftBoundRel of a size the turn leaves alone; only
    // the rounding of the turned corners (~1e-15 relative) may differ.
    EXPECT_GT(a.drift_bound, 0);
    EXPECT_NEAR(b.drift_bound, a.drift_bound, 1e-12 * a.drift_bound);
    // That size is the block's own (the largest distance between two of
    // its corners), in metres, whatever its frame.
    EXPECT_NEAR(a.drift_bound, kDriftBoundRel * diameter(here), 1e-12 * a.drift_bound);
  }
}

TEST(MotionFrame, TheUnitsOfIntegrationDoNotDependOnTheFrame) {
  const Placement at = turned_37_degrees();
  const blocks::Polyhedron here = wedge(), turned = wedge(at);
  const blocks::MassProperties mass_here = blocks::mass_properties(here, 2700),
                               mass_turned = blocks::mass_properties(turned, 2700);
  const kinematics::Effects g_here = gravity(), g_turned = gravity(at);
  const BlockMotion m_here(here, mass_here, block_loads(here, mass_here, g_here),
                           friction_on_joints(here, 30));
  const BlockMotion m_turned(turned, mass_turned, block_loads(turned, mass_turned, g_turned),
                             friction_on_joints(turned, 30));
  const dynamics_phases::Scales a = dynamics_phases::block_scales(m_here),
                                b = dynamics_phases::block_scales(m_turned);
  // Rounding of the turned corners only (~1e-15 relative).
  EXPECT_NEAR(b.length, a.length, 1e-12 * a.length);
  EXPECT_NEAR(b.time, a.time, 1e-12 * a.time);
}

}  // namespace
}  // namespace rockface::mechanics
