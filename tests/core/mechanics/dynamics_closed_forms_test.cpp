// The block's motion after failure against closed forms: a slab sliding on
// an inclined plane with friction, a wedge sliding along the intersection
// of its two planes, a column turning about its edge, free fall and the
// landing point of a projectile, a stable block that does not move.
//
// Tolerances: the stepper keeps the local error per step below
// abs 1e-10 + rel 1e-8 of the block's size (standard preset) over ~100-200
// steps, so displacements are good to ~1e-7 of the block's size; the
// tests allow 1e-6 of it (ten times that) unless they say otherwise.
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/units.h"
#include "core/kinematics/effects/effect_seismic.h"
#include "tests/core/mechanics/dynamics_support.h"

namespace rockface::mechanics {
namespace {

using namespace testing;

TEST(BlockDynamics, SlabSlidesDownAnInclinedPlaneWithFriction) {
  const Slab slab;  // 35 degrees, 4 m down the dip, 1.5 m thick
  const blocks::Polyhedron block = slab.block();
  const double phi = 20;
  const BlockDynamics d = run(block, phi, gravity(), options(0.8, 0.1));
  const double alpha = deg_to_rad(slab.psi), mu = std::tan(deg_to_rad(phi));
  const double acc = kG * (std::sin(alpha) - mu * std::cos(alpha));
  ASSERT_GE(d.samples.size(), 9u);
  for (const MotionSample& s : d.samples) {
    const Eigen::Vector3d u = s.centroid - d.samples.front().centroid;
    const double x = 0.5 * acc * s.time * s.time;
    // Integration error: 1e-6 of the block's size (see the header).
    EXPECT_NEAR(u.dot(slab.d()), x, 1e-6 * block.size()) << "t = " << s.time;
    EXPECT_NEAR((u - u.dot(slab.d()) * slab.d()).norm(), 0, 1e-6 * block.size());
    // No rotation while the whole slab is over the joint (rounding only).
    EXPECT_LT(s.orientation.vec().norm(), 1e-9);
    // Energy: the work of gravity less the friction's m g cos(alpha) mu x.
    const double friction_work = d.mass * kG * std::cos(alpha) * mu * x;
    EXPECT_NEAR(s.dissipated, friction_work, 1e-6 * d.mass * kG * block.size());
  }
  ASSERT_FALSE(d.events.empty());
  EXPECT_EQ(d.events.front().what, "slides on J1");
  EXPECT_EQ(d.events.front().time, 0.0);
}

TEST(BlockDynamics, WedgeSlidesAlongTheIntersectionOfItsPlanes) {
  const blocks::Polyhedron block = wedge();
  const double phi = 20, mu = std::tan(deg_to_rad(phi));
  const BlockDynamics d = run(block, phi, gravity(), options(0.5, 0.1));
  // Closed form: the line of intersection s (downwards), the normal forces
  // from the weight's part across s: m g_perp = -(N1 n1 + N2 n2), and
  // m a = m g.s - mu (N1 + N2).
  const Eigen::Vector3d n1 = block.planes()[0].inward_normal(),
                        n2 = block.planes()[1].inward_normal();
  Eigen::Vector3d s = n1.cross(n2).normalized();
  if (s.z() > 0) s = -s;
  const Eigen::Vector3d g(0, 0, -kG);
  const Eigen::Vector3d g_perp = g - g.dot(s) * s;
  Eigen::Matrix<double, 3, 2> a;
  a << n1, n2;
  const Eigen::Vector2d n = a.colPivHouseholderQr().solve(-g_perp);  // per unit mass
  ASSERT_GT(n(0), 0);
  ASSERT_GT(n(1), 0);
  const double acc = g.dot(s) - mu * (n(0) + n(1));
  ASSERT_GT(acc, 0);
  for (const MotionSample& smp : d.samples) {
    const Eigen::Vector3d u = smp.centroid - d.samples.front().centroid;
    EXPECT_NEAR(u.dot(s), 0.5 * acc * smp.time * smp.time, 1e-6 * block.size()) << smp.time;
    EXPECT_NEAR((u - u.dot(s) * s).norm(), 0, 1e-6 * block.size());
  }
  EXPECT_EQ(d.events.front().what, "slides on J1 and J2");
  // Constraint drift stays within the stated bound over the whole run.
  EXPECT_LE(d.drift_after, d.drift_bound);
  EXPECT_LT(d.quaternion_error, 1e-12);  // renormalised after every step
}

// A leaning column on a level joint: base 1 x 1 m on J1 (z = 0), 4 m
// high, its sides L1 and L2 leaning at tan = 0.4 towards +x, so that its
// centroid (x = 1.3 m) lies beyond the base's edge on L2 (x = 1): it
// topples about that edge.
blocks::Polyhedron leaning_column() {
  using blocks::PlaneKind;
  const Placement at;
  const Eigen::Vector3d lean = Eigen::Vector3d(1, 0, -0.4).normalized();
  return bounded("column",
                 {bounding(0, "J1", PlaneKind::Joint, {0, 0, 1}, {0, 0, 0}, at),
                  bounding(1, "top", PlaneKind::FreeFace, {0, 0, -1}, {0, 0, 4}, at),
                  bounding(2, "L1", PlaneKind::FreeFace, lean, {0, 0, 0}, at),
                  bounding(3, "L2", PlaneKind::FreeFace, -lean, {1, 0, 0}, at),
                  bounding(4, "S1", PlaneKind::FreeFace, {0, 1, 0}, {0, 0, 0}, at),
                  bounding(5, "S2", PlaneKind::FreeFace, {0, -1, 0}, {0, 1, 0}, at)},
                 at);
}

TEST(BlockDynamics, FrictionlessColumnTurnsAboutItsEdgeAndConservesEnergy) {
  const blocks::Polyhedron block = leaning_column();
  const BlockDynamics d = run(block, 0, gravity(), options(1.2, 0.05));
  ASSERT_GE(d.events.size(), 2u);
  EXPECT_EQ(d.events.front().what, "rotates about edge J1-L2");
  double work = 0;
  for (const MotionSample& s : d.samples) {
    // Frictionless contacts do no work: kinetic energy = work of gravity.
    // Integration error ~1e-7 of m g L (see the header); allowed 1e-6.
    EXPECT_NEAR(s.dissipated, 0, 1e-6 * d.mass * kG * block.size()) << s.time;
    // Nothing pushes it sideways: the centroid falls on its vertical.
    const Eigen::Vector3d u = s.centroid - d.samples.front().centroid;
    EXPECT_NEAR(u.head<2>().norm(), 0, 1e-6 * block.size()) << s.time;
    work = std::max(work, s.work);
  }
  EXPECT_GT(work, 0.05 * d.mass * kG * block.size());  // it did fall
  // It tips: the edge leaves J1 and it falls freely.
  EXPECT_NE(find_event(d, "leaves"), nullptr);
}

TEST(BlockDynamics, ColumnOnARoughJointTurnsAboutAFixedEdge) {
  const blocks::Polyhedron block = leaning_column();
  const BlockDynamics d = run(block, 60, gravity(), options(0.6, 0.05));
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  // The pivot: the base's edge x = 1, z = 0, along y.
  const Eigen::Vector3d pivot(1, 0.5, 0), axis = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d r0 = mass.centroid - pivot;
  const Eigen::Vector3d r_perp = r0 - r0.dot(axis) * axis;
  const double i_edge = axis.dot(mass.inertia * axis) + mass.mass * r_perp.squaredNorm();
  EXPECT_EQ(d.events.front().what, "rotates about edge J1-L2");
  int checked = 0;
  for (const MotionSample& s : d.samples) {
    const Eigen::Vector3d r = s.centroid - pivot;
    if (find_event(d, "leaves") && s.time >= find_event(d, "leaves")->time) break;
    // The edge stays put: the centroid keeps its distance from it.
    EXPECT_NEAR((r - r.dot(axis) * axis).norm(), r_perp.norm(), 1e-6 * block.size());
    // Rotation about a fixed axis: 1/2 I_edge w^2 = m g (drop of the centroid).
    const double drop = d.samples.front().centroid.z() - s.centroid.z();
    const double w = std::sqrt(2 * mass.mass * kG * drop / i_edge);
    EXPECT_NEAR(s.angular_velocity.norm(), w, 1e-6 * std::sqrt(kG / block.size()));
    if (s.time > 0) {
      EXPECT_NEAR(s.angular_velocity.normalized().dot(axis), 1.0, 1e-9);  // top turns to +x
    }
    ++checked;
  }
  EXPECT_GE(checked, 5);
  EXPECT_LE(d.drift_after, d.drift_bound);
}

// A block under a roof: its joints open under gravity and it falls.
blocks::Polyhedron roof_block(const Placement& at = {}) {
  using blocks::PlaneKind;
  return bounded("roof",
                 {bounding(0, "J1", PlaneKind::Joint, -normal_deg(50, 0), {0, 0, 0}, at),
                  bounding(1, "J2", PlaneKind::Joint, -normal_deg(50, 120), {0, 0, 0}, at),
                  bounding(2, "J3", PlaneKind::Joint, -normal_deg(50, 240), {0, 0, 0}, at),
                  bounding(3, "R", PlaneKind::FreeFace, normal_deg(0, 0), {0, 0, -2}, at)},
                 at);
}

TEST(BlockDynamics, RoofBlockFallsFreelyAndLandsOnTheFloor) {
  const blocks::Polyhedron block = roof_block();
  DynamicsOptions o = options(0.5, 0.05);
  o.floor = DynamicsFloor{Eigen::Vector3d(0, 0, -7), Eigen::Vector3d::UnitZ()};
  const BlockDynamics d = run(block, 30, gravity(), o);
  ASSERT_FALSE(d.events.empty());
  EXPECT_EQ(d.events.front().kind, "free_fall");
  for (const MotionSample& s : d.samples) {
    const Eigen::Vector3d u = s.centroid - d.samples.front().centroid;
    EXPECT_NEAR(u.z(), -0.5 * kG * s.time * s.time, 1e-6 * block.size()) << s.time;
    EXPECT_NEAR(u.head<2>().norm(), 0, 1e-9 * block.size());
  }
  // It falls 5 m from the roof (z = -2) to the floor (z = -7): free flight
  // goes on past the duration to the landing.
  ASSERT_TRUE(d.landing);
  const double t = std::sqrt(2 * 5.0 / kG);
  // The landing time is found by bisection to 1e-9 T; integration 1e-7.
  EXPECT_NEAR(d.landing->time, t, 1e-6);
  EXPECT_NEAR(d.landing->speed, kG * t, 1e-5);
  EXPECT_NEAR(d.landing->kinetic_translational, 0.5 * d.mass * kG * kG * t * t,
              1e-6 * d.mass * kG * 5.0);
  EXPECT_EQ(d.outcome, "lands");
  EXPECT_EQ(d.events.back().kind, "lands");
}

TEST(BlockDynamics, ProjectileLandingPointUnderGravityAndAHorizontalAcceleration) {
  const blocks::Polyhedron block = roof_block();
  kinematics::Effects e = gravity();
  const Eigen::Vector3d ah(3.0, -1.5, 0);  // pseudo-static, m/s^2
  e.push_back(std::make_unique<kinematics::SeismicEffect>(ah));
  DynamicsOptions o = options(0.5, 0.05);
  o.floor = DynamicsFloor{Eigen::Vector3d(0, 0, -7), Eigen::Vector3d::UnitZ()};
  const BlockDynamics d = run(block, 30, e, o);
  ASSERT_TRUE(d.landing);
  // From rest under the constant acceleration (ah, -g): the corner lands
  // after t = sqrt(2 h / g) at a horizontal offset of ah t^2 / 2.
  const double t = std::sqrt(2 * 5.0 / kG);
  EXPECT_NEAR(d.landing->time, t, 1e-6);
  const Eigen::Vector3d u = d.landing->centroid - d.samples.front().centroid;
  EXPECT_NEAR(u.x(), 0.5 * ah.x() * t * t, 1e-5);
  EXPECT_NEAR(u.y(), 0.5 * ah.y() * t * t, 1e-5);
  EXPECT_NEAR(d.landing->point.z(), -7.0, 1e-6);
}

TEST(BlockDynamics, StableBlockDoesNotMove) {
  const Slab slab;  // 35 degrees
  const blocks::Polyhedron block = slab.block();
  const BlockDynamics d = run(block, 40, gravity(), options(1.0, 0.25));
  ASSERT_FALSE(d.samples.empty());
  for (const MotionSample& s : d.samples) {
    // Static friction holds: nothing but rounding may move it.
    EXPECT_LT((s.centroid - d.samples.front().centroid).norm(), 1e-12 * block.size());
    EXPECT_LT(s.velocity.norm(), 1e-12);
  }
  EXPECT_EQ(d.events.front().kind, "rest");
  EXPECT_EQ(d.outcome, "at rest");
}

}  // namespace
}  // namespace rockface::mechanics
