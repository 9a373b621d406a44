// Geometry that breaks naive block code: slivers, blocks from 1 mm to 100 m,
// near-degenerate corners, survey coordinates, rigid motion and reordering.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/blocks/construction.h"
#include "core/blocks/convexity.h"
#include "core/blocks/mass_properties.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "tests/core/blocks/block_shapes.h"

namespace rockface::blocks {
namespace {

using geometry::HalfSpace;
using test::halfspace;

TEST(BlockHardCases, SliverPlateKeepsItsTopologyAndVolume) {
  // 10 m x 10 m x 10 micrometres: thickness 1e-6 of the length. Corners
  // come from 3x3 solves with ~1e-16 relative error on coordinates of ~10 m,
  // i.e. ~1e-15 m on a 1e-5 m thickness: volume to ~1e-10 relative; 1e-8
  // leaves a margin for the summation of the tetrahedra.
  const double L = 10, t = 1e-5;
  const auto c = build_convex_block("sliver", test::box_halfspaces(L, L, t, {3, -7, 2}));
  ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
  EXPECT_EQ(c.polyhedron->vertices().size(), 8u);
  EXPECT_EQ(c.polyhedron->faces().size(), 6u);
  const MassProperties mp = mass_properties(*c.polyhedron, 1);
  EXPECT_NEAR(mp.volume, L * L * t, L * L * t * 1e-8);
  // The thin direction has the largest principal moment m (2 L^2) / 12.
  EXPECT_NEAR(mp.principal_moments[2], mp.mass * 2 * L * L / 12, mp.mass * L * L * 1e-8);
  EXPECT_NEAR(std::abs(mp.principal_axes.col(2).z()), 1, 1e-12);
  EXPECT_TRUE(is_convex(*c.polyhedron));

  // The same plate given by vertices and faces.
  const Polyhedron f = test::build(test::prism(test::rectangle(L, L), 0, t));
  EXPECT_NEAR(mass_properties(f, 1).volume, L * L * t, L * L * t * 1e-12);
}

TEST(BlockHardCases, SliverWedgeBetweenNearlyParallelPlanes) {
  // Two planes through the x axis at an angle of 1e-6 rad, cut by x = 0,
  // x = 1 and y = 1: a triangular prism with cross-section area
  // tan(1e-6) / 2.
  const double a = 1e-6;
  std::vector<HalfSpaceInput> h{
      halfspace(0, "J0", PlaneKind::Joint, {0, 0, 1}, {0, 0, 0}, HalfSpace::Upper),
      halfspace(1, "J1", PlaneKind::Joint, {0, -std::sin(a), std::cos(a)}, {0, 0, 0},
                HalfSpace::Lower),
      halfspace(2, "X0", PlaneKind::FreeFace, {1, 0, 0}, {0, 0, 0}, HalfSpace::Upper),
      halfspace(3, "X1", PlaneKind::FreeFace, {1, 0, 0}, {1, 0, 0}, HalfSpace::Lower),
      halfspace(4, "Y1", PlaneKind::FreeFace, {0, 1, 0}, {0, 1, 0}, HalfSpace::Lower)};
  const auto c = build_convex_block("wedge", h);
  ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
  EXPECT_EQ(c.polyhedron->vertices().size(), 6u);
  // The thin end is exact (planes through the x axis); the wide end's
  // corners carry ~1e-16 m: 1e-9 relative of a 5e-7 m^3 volume.
  EXPECT_NEAR(mass_properties(*c.polyhedron, 1).volume, std::tan(a) / 2, std::tan(a) / 2 * 1e-9);
}

TEST(BlockHardCases, SameBlockFromOneMillimetreToOneHundredMetres) {
  const auto shape = test::prism(test::l_shape(1.0), 0, 0.6);
  const MassProperties unit = mass_properties(test::build(shape), 2700);
  for (double s : {1e-3, 1e-1, 1.0, 10.0, 100.0}) {
    auto scaled = shape;
    for (auto& v : scaled.vertices) v *= s;
    const Polyhedron p = test::build(scaled);
    EXPECT_EQ(p.edges().size(), 18u);
    EXPECT_FALSE(is_convex(p));
    const MassProperties mp = mass_properties(p, 2700);
    // Volume scales with s^3, inertia with s^5; double rounding only: 1e-12.
    EXPECT_NEAR(mp.volume / (s * s * s), unit.volume, unit.volume * 1e-12) << s;
    EXPECT_LE((mp.inertia / std::pow(s, 5) - unit.inertia).norm(), unit.inertia.norm() * 1e-12)
        << s;
  }
  // From half-spaces too: a 1 mm and a 100 m cube both have 8 corners.
  for (double s : {1e-3, 100.0}) {
    const auto c = build_convex_block("cube", test::box_halfspaces(s, s, s, {s, 2 * s, -s}));
    ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
    EXPECT_EQ(c.polyhedron->vertices().size(), 8u);
    EXPECT_NEAR(mass_properties(*c.polyhedron, 1).volume, s * s * s, s * s * s * 1e-12);
  }
}

// A square pyramid (base 2 x 2 on z = 0, apex (0, 0, 1)) whose four side
// planes miss the common apex by +-delta along their normals.
ConvexConstruction pyramid(double delta) {
  std::vector<HalfSpaceInput> h;
  for (int k = 0; k < 4; ++k) {
    const double az = k * std::numbers::pi / 2;
    const Eigen::Vector3d out = Eigen::Vector3d(std::cos(az), std::sin(az), 1.0).normalized();
    const double shift = (k % 2 ? 1 : -1) * delta;
    h.push_back(halfspace(k, "J" + std::to_string(k), PlaneKind::Joint, out,
                          Eigen::Vector3d(0, 0, 1) + shift * out, HalfSpace::Lower));
  }
  h.push_back(halfspace(4, "F", PlaneKind::FreeFace, Eigen::Vector3d::UnitZ(),
                        Eigen::Vector3d::Zero(), HalfSpace::Upper));
  return build_convex_block("pyramid", h);
}

TEST(BlockHardCases, NearDegenerateCornerIsStable) {
  // Exactly degenerate and below the merge distance (1e-9 of the size): one
  // apex. Above it: a tiny ridge with two corners, still a valid polyhedron.
  // In every case the volume moves continuously with delta: the shifted
  // planes change it by ~ perimeter x height x delta ~ 6 delta.
  for (double delta : {0.0, 1e-15, 1e-12, 1e-10, 1e-7, 1e-5}) {
    const ConvexConstruction c = pyramid(delta);
    ASSERT_EQ(c.outcome, ConvexOutcome::Bounded) << delta;
    const Polyhedron& p = *c.polyhedron;
    const double vol = mass_properties(p, 1).volume;
    EXPECT_NEAR(vol, 4.0 / 3, 10 * delta + 1e-12) << delta;
    const int v = static_cast<int>(p.vertices().size());
    if (delta < 1e-9) {
      EXPECT_EQ(v, 5) << delta;
    } else {
      EXPECT_EQ(v, 6) << delta;  // the apex splits into the two ends of a ridge
    }
    EXPECT_EQ(v - static_cast<int>(p.edges().size()) + static_cast<int>(p.faces().size()), 2);
    EXPECT_TRUE(is_convex(p));
  }
}

TEST(BlockHardCases, SurveyCoordinatesThroughADatum) {
  // The same box with its planes through points at 1e6 m: given relative to
  // a datum it is the box at the origin, to the rounding of the datum
  // subtraction (1.2e-10 m at 1e6 m).
  const Eigen::Vector3d far(512340.0, 5211870.0, 410.0);
  const auto near = build_convex_block("B", test::box_halfspaces(2, 3, 1));
  auto shifted = test::box_halfspaces(2, 3, 1, far);
  for (auto& h : shifted) h.plane = h.plane.shifted(far);
  const auto c = build_convex_block("B", shifted, far);
  ASSERT_EQ(c.outcome, ConvexOutcome::Bounded);
  const MassProperties a = mass_properties(*near.polyhedron, 2700);
  const MassProperties b = mass_properties(*c.polyhedron, 2700);
  EXPECT_NEAR(b.volume, a.volume, a.volume * 1e-9);
  EXPECT_LE((b.centroid + c.polyhedron->datum() - far - a.centroid).norm(), 1e-9);
  EXPECT_LE((b.inertia - a.inertia).norm(), a.inertia.norm() * 1e-9);
}

TEST(BlockHardCases, VerdictsSurviveRigidMotionAndReordering) {
  // A wedge (two joints, face, crest) turned about the vertical by 37
  // degrees, moved, and its half-spaces reversed in order: same verdicts,
  // margins, mode planes and factor of safety.
  auto wedge = [](double turn, const Eigen::Vector3d& at, bool reverse) {
    auto n = [&](double dip, double dipdir) {
      return geometry::plane_normal_deg(dip, dipdir + turn);
    };
    std::vector<HalfSpaceInput> h{
        halfspace(0, "J1", PlaneKind::Joint, n(55, 140), at, HalfSpace::Upper),
        halfspace(1, "J2", PlaneKind::Joint, n(65, 230), at, HalfSpace::Upper),
        halfspace(2, "F", PlaneKind::FreeFace, n(80, 185), at, HalfSpace::Lower),
        halfspace(3, "T", PlaneKind::FreeFace, n(5, 190), at + Eigen::Vector3d(0, 0, 12),
                  HalfSpace::Lower)};
    if (reverse) std::reverse(h.begin(), h.end());
    return *build_convex_block("w", h).polyhedron;
  };
  kinematics::Effects g;
  g.push_back(std::make_unique<kinematics::GravityEffect>(Eigen::Vector3d(0, 0, -9.81)));
  auto analyse = [&](const Polyhedron& p) {
    kinematics::BlockAnalysisInput in;
    in.density = 2650;
    in.strengths.assign(p.planes().size(), {deg_to_rad(32), 0});
    in.effects = &g;
    in.uncertainty = deg_to_rad(1);
    return kinematics::analyse_block(p, in);
  };
  const Polyhedron p0 = wedge(0, Eigen::Vector3d::Zero(), false);
  const auto r0 = analyse(p0);
  ASSERT_TRUE(r0.mode && r0.fos);
  for (const auto& [turn, reverse] :
       {std::pair{37.0, false}, std::pair{0.0, true}, std::pair{-121.0, true}}) {
    const Polyhedron p = wedge(turn, Eigen::Vector3d(40, -25, 300), reverse);
    const auto r = analyse(p);
    EXPECT_EQ(r.finiteness.removable.value, r0.finiteness.removable.value);
    // Margins are angles between the same normals: rounding only.
    EXPECT_NEAR(r.finiteness.removable.margin, r0.finiteness.removable.margin, 1e-12);
    ASSERT_TRUE(r.mode && r.fos);
    EXPECT_EQ(r.mode->type, r0.mode->type);
    std::vector<std::string> a, b;
    for (int q : r.mode->planes) a.push_back(p.planes()[q].name);
    for (int q : r0.mode->planes) b.push_back(p0.planes()[q].name);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
    EXPECT_NEAR(*r.fos, *r0.fos, *r0.fos * 1e-10);
    EXPECT_NEAR(r.mass.volume, r0.mass.volume, r0.mass.volume * 1e-10);
  }
}

}  // namespace
}  // namespace rockface::blocks
