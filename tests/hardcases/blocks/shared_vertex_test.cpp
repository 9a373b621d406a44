// Four or more planes through one surveyed vertex (issue 40): the points of
// the planes moved by 1e-11 to 1e-5 m, as a survey gives them, or a joint
// 1e-7 to 1 degree from another passing 1e-11 to 1e-7 m off their shared
// vertex. Every draw must give a block (never an exception), whose volume is
// the exact pyramid's within what the moves can change, with the verdicts
// of the unmoved block.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/blocks/construction.h"
#include "core/blocks/convexity.h"
#include "core/blocks/mass_properties.h"
#include "core/blocks/tolerances.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "tests/hardcases/blocks/surveyed_pyramid.h"

namespace rockface::blocks {
namespace {

using test::exact_volume;
using test::halfspaces;
using test::log_uniform;
using test::Pyramid;
using test::random_pyramid;
using test::surface_area;
using test::text;

kinematics::BlockAnalysis analyse(const Polyhedron& p, const kinematics::Effects& g) {
  kinematics::BlockAnalysisInput in;
  in.density = 2650;
  in.strengths.assign(p.planes().size(), {deg_to_rad(30), 0});
  in.effects = &g;
  in.uncertainty = deg_to_rad(1);
  return kinematics::analyse_block(p, in);
}

kinematics::Effects gravity() {
  kinematics::Effects g;
  g.push_back(std::make_unique<kinematics::GravityEffect>(Eigen::Vector3d(0, 0, -9.81)));
  return g;
}

// Moving planes (by at most delta along their normals) cannot change the
// volume of a convex block by more than its surface area x delta, to first
// order. The construction adds its own: a corner within kVertexMergeRel x
// size of a plane is on it, and corners that close are one (each moves a
// face by at most that much, twice). The second order is below 1e-5 of the
// first for delta / size <= 1e-5, which the 1 % allows for; the exact volume
// itself is the 2D clip's, ~1e-13 relative (roundings of coordinates of
// ~10 m).
void expect_volume_near_exact(const Polyhedron& p, double exact, double delta) {
  const double volume = mass_properties(p, 1).volume;
  const double snap = 2 * kVertexMergeRel * p.size();
  EXPECT_NEAR(volume, exact, 1.01 * surface_area(p) * (delta + snap) + 1e-12 * exact);
}

// The verdicts of a moved block are the unmoved one's, or marginal: moves
// do not turn a plane, so removability, mode and FoS (a function of the
// sliding planes' normals) keep their values to rounding.
void expect_same_verdicts(const Polyhedron& moved, const Polyhedron& exact,
                          const kinematics::Effects& g) {
  const auto a = analyse(moved, g), b = analyse(exact, g);
  if (!a.finiteness.removable.marginal && !b.finiteness.removable.marginal) {
    EXPECT_EQ(a.finiteness.removable.value, b.finiteness.removable.value);
  }
  ASSERT_EQ(a.mode.has_value(), b.mode.has_value());
  if (!a.mode) return;
  if (a.mode->marginal || b.mode->marginal) return;
  EXPECT_EQ(a.mode->type, b.mode->type);
  ASSERT_EQ(a.fos.has_value(), b.fos.has_value());
  // The FoS depends on normals only: rounding, ~1e-15 per operation.
  if (a.fos) {
    EXPECT_NEAR(*a.fos, *b.fos, 1e-9 * std::abs(*b.fos));
  }
}

TEST(SharedVertexHardCases, FourOrMorePlanesThroughASurveyedVertex) {
  std::mt19937_64 rng(40);
  const kinematics::Effects g = gravity();
  for (int draw = 0; draw < 600; ++draw) {
    std::uniform_int_distribution<int> planes(4, 6);
    Pyramid p = random_pyramid(rng, planes(rng));
    const double exact = exact_volume(p);
    const auto unmoved = build_convex_block("W", halfspaces(p));
    ASSERT_EQ(unmoved.outcome, ConvexOutcome::Bounded) << draw;
    const double delta = log_uniform(rng, 1e-11, 1e-5);
    for (auto& x : p.points) x += delta * Eigen::Vector3d::Random().normalized();
    SCOPED_TRACE("draw " + std::to_string(draw) + ", points moved by up to " + text(delta) + " m");
    ConvexConstruction c;
    ASSERT_NO_THROW(c = build_convex_block("W", halfspaces(p)));
    ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
    const Polyhedron& moved = *c.polyhedron;
    EXPECT_TRUE(is_convex(moved));
    expect_volume_near_exact(moved, exact, delta);
    expect_same_verdicts(moved, *unmoved.polyhedron, g);
  }
}

TEST(SharedVertexHardCases, NearParallelJointOffTheSharedVertex) {
  std::mt19937_64 rng(41);
  const kinematics::Effects g = gravity();
  for (int draw = 0; draw < 600; ++draw) {
    std::uniform_int_distribution<int> planes(3, 5);
    Pyramid p = random_pyramid(rng, planes(rng));
    // K: the first joint turned by 1e-7 to 1 degree about a random axis
    // through the apex, then moved off it by 1e-11 to 1e-7 m.
    const double angle = deg_to_rad(log_uniform(rng, 1e-7, 1.0));
    const Eigen::Vector3d axis = Eigen::Vector3d::Random().normalized();
    Eigen::Vector3d k = Eigen::AngleAxisd(angle, axis) * p.normals[0];
    if (k.z() < 0) k = -k;  // still an upward normal: the rock below it
    p.normals.push_back(k.normalized());
    p.points.push_back(p.apex);
    const double exact = exact_volume(p);
    const auto unmoved = build_convex_block("W", halfspaces(p));
    ASSERT_EQ(unmoved.outcome, ConvexOutcome::Bounded) << draw;
    std::uniform_real_distribution<double> sign(-1, 1);
    const double off = log_uniform(rng, 1e-11, 1e-7);
    p.points.back() += (sign(rng) < 0 ? -off : off) * p.normals.back();
    SCOPED_TRACE("draw " + std::to_string(draw) + ", K " + text(rad_to_deg(angle)) +
                 " deg from J0, " + text(off) + " m off the vertex");
    ConvexConstruction c;
    ASSERT_NO_THROW(c = build_convex_block("W", halfspaces(p)));
    ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
    const Polyhedron& moved = *c.polyhedron;
    EXPECT_TRUE(is_convex(moved));
    expect_volume_near_exact(moved, exact, off);
    expect_same_verdicts(moved, *unmoved.polyhedron, g);
  }
}

}  // namespace
}  // namespace rockface::blocks
