// Geometry that breaks naive rotation checks: a lever arm along a joint
// normal (the limit plane n x (R - C) vanishes), corners where four planes
// meet, corners on free faces only, survey coordinates, rigid motions,
// reordering and tiny perturbations. Each case asserts a stable answer or an
// honest "marginal".
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/common/units.h"
#include "core/kinematics/remote_axis.h"
#include "core/kinematics/rotation_space.h"
#include "tests/support/rotation_blocks.h"

namespace rockface::kinematics {
namespace {

using Eigen::Vector3d;
using test_rotation::Side;

constexpr double kUncertainty = deg_to_rad(1.0);

const CornerRotation& corner(const RotationAnalysis& a, int v) {
  const auto it = std::find_if(a.corners.begin(), a.corners.end(),
                               [&](const CornerRotation& c) { return c.vertex == v; });
  if (it == a.corners.end()) throw std::runtime_error("not a static point");
  return *it;
}

// The corner tetrahedron: joints x = 0, y = 0, z = 0 through the apex
// A = (0,0,0), free face x + y + z = 1 through B = (1,0,0), D = (0,1,0),
// E = (0,0,1). From B, the apex lies straight along the normal of joint
// x = 0: (A - B) x (1,0,0) = 0.
std::vector<Side> corner_tetrahedron(const Vector3d& tilt_x = Vector3d::Zero()) {
  return {{"Jx", true, Vector3d(1, 0, 0) + tilt_x, {0, 0, 0}},
          {"Jy", true, {0, 1, 0}, {0, 0, 0}},
          {"Jz", true, {0, 0, 1}, {0, 0, 0}},
          {"F", false, {-1, -1, -1}, {1, 0, 0}}};
}

TEST(RotationHardCases, LeverArmAlongAJointNormalIsVoidAndTheCornerLiftsOff) {
  const RotationInput in = test_rotation::convex_block("corner", corner_tetrahedron());
  const RotationAnalysis a = analyse_rotation(in, kUncertainty);
  const int ib = test_rotation::corner_at(in, {1, 0, 0});
  const int ia = test_rotation::corner_at(in, {0, 0, 0});
  const CornerRotation& b = corner(a, ib);
  // By hand, R = B: A - B = (-1,0,0): with Jx void; Jy (0,0,-1), Jz (0,1,0).
  // D - B = (-1,1,0): Jx (0,0,-1), Jz (1,1,0). E - B = (-1,0,1): Jx (0,1,0),
  // Jy (-1,0,-1). Six limit planes (two repeated directions), one void.
  EXPECT_EQ(b.void_limits, 1);
  EXPECT_EQ(b.limits.size(), 6u);
  for (const auto& l : b.limits) EXPECT_FALSE(l.corner == ia && in.planes[l.plane].name == "Jx");
  // Space {u_z <= 0, u_y >= 0, u_x + u_y >= 0, -u_x - u_z >= 0}: the
  // witness (0,1,-1)/sqrt2 is inside by 30 degrees at least.
  EXPECT_TRUE(b.rotatable.value);
  EXPECT_GE(b.signed_margin, deg_to_rad(30) - 1e-12);
  EXPECT_FALSE(b.rotatable.marginal);

  // Why void is right: for every feasible axis, a finite rotation by a small
  // angle w keeps A on the block side of Jx: its x goes from 0 to
  // w^2/2 |A - B| (1 - u_x^2) + O(w^3) >= 0. Checked with exact rotations.
  std::mt19937 gen(5);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vector3d u =
        Vector3d(std::normal_distribution<>()(gen), std::normal_distribution<>()(gen),
                 std::normal_distribution<>()(gen))
            .normalized();
    if (b.space.margin_of(u) < 0) continue;
    ++checked;
    for (double w : {1e-4, 1e-3, 1e-2}) {
      const Vector3d moved = Vector3d(1, 0, 0) + Eigen::AngleAxisd(w, u) * Vector3d(-1, 0, 0);
      const double expect = w * w / 2 * (1 - u.x() * u.x());
      // O(w^3) remainder: |A - B| w^3 / 6 bounds it.
      EXPECT_NEAR(moved.x(), expect, w * w * w / 6 + 1e-16);
      EXPECT_GE(moved.x(), -1e-16);  // rounding of the rotation only
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(RotationHardCases, TiltedJointNearTheVoidCaseIsStableOrMarginal) {
  const RotationInput in0 = test_rotation::convex_block("corner", corner_tetrahedron());
  const RotationAnalysis a0 = analyse_rotation(in0, kUncertainty);
  const bool b0 = corner(a0, test_rotation::corner_at(in0, {1, 0, 0})).rotatable.value;
  int flipped = 0;
  for (double eps : {1e-12, 1e-10, 1e-7, 1e-4}) {
    for (const Vector3d& dir :
         {Vector3d(0, 1, 0), Vector3d(0, -1, 0), Vector3d(0, 0, 1), Vector3d(0, 0, -1)}) {
      SCOPED_TRACE("tilt " + std::to_string(eps));
      // Tilting Jx about its own trace leaves the corner A where it is but
      // turns the normal off the lever arm B -> A by eps.
      const RotationInput in = test_rotation::convex_block("corner", corner_tetrahedron(eps * dir));
      const RotationAnalysis a = analyse_rotation(in, kUncertainty);
      const CornerRotation& b = corner(a, test_rotation::corner_at(in, {1, 0, 0}));
      if (b.rotatable.value != b0) {
        ++flipped;
        EXPECT_TRUE(b.rotatable.marginal);  // a flip is never silent
      }
    }
  }
  // Some tilts do decide the other way (they close u_z or u_y): those must
  // be the marginal ones above.
  EXPECT_GT(flipped, 0);
}

// A square pyramid: apex (0,0,2) where four planes meet, base square of
// side 2 on the joint z = 0. `free_side` chooses which side face is free.
std::vector<Side> pyramid(int free_side) {
  std::vector<Side> s = {{"Jbase", true, {0, 0, 1}, {0, 0, 0}}};
  const std::vector<Vector3d> out = {{0, 2, 1}, {2, 0, 1}, {0, -2, 1}, {-2, 0, 1}};
  const std::vector<std::string> names = {"N", "E", "S", "W"};
  for (int i = 0; i < 4; ++i)
    s.push_back({(i == free_side ? "F" : "J") + names[i], i != free_side, -out[i], {0, 0, 2}});
  return s;
}

TEST(RotationHardCases, FourPlanesAtTheStaticPoint) {
  const RotationInput in = test_rotation::convex_block("pyramid", pyramid(0));
  ASSERT_EQ(in.vertices.size(), 5u);  // the four side planes meet in one apex
  const int apex = test_rotation::corner_at(in, {0, 0, 2});
  const RotationTopology t = rotation_topology(in);
  ASSERT_EQ(t.vertex_planes[apex].size(), 4u);
  const RotationAnalysis a = analyse_rotation(in, kUncertainty);
  const CornerRotation& c = corner(a, apex);
  // By hand: the four base corners C = (+-1, +-1, 0) lie on the base joint
  // (n = +z); their limit planes from the apex, (C - apex) x z = (y_C, -x_C, 0),
  // point into all four horizontal quadrants, so only the vertical axis
  // satisfies all four: the rotation space has no interior.
  EXPECT_FALSE(c.rotatable.value);
  EXPECT_LE(c.signed_margin, 1e-12);
  // Same verdicts and margins with the planes in reverse order.
  std::vector<Side> rev = pyramid(0);
  std::reverse(rev.begin(), rev.end());
  const RotationInput in_rev = test_rotation::convex_block("pyramid", rev);
  const RotationAnalysis a_rev = analyse_rotation(in_rev, kUncertainty);
  ASSERT_EQ(a_rev.corners.size(), a.corners.size());
  for (const auto& cr : a.corners) {
    const CornerRotation& other =
        corner(a_rev, test_rotation::corner_at(in_rev, in.vertices[cr.vertex]));
    EXPECT_EQ(other.rotatable.value, cr.rotatable.value);
    EXPECT_NEAR(other.signed_margin, cr.signed_margin, 1e-12);  // same planes, rounding only
  }
}

TEST(RotationHardCases, FourPlanesSplitByATinyPerturbationKeepTheirVerdicts) {
  const RotationInput in = test_rotation::convex_block("pyramid", pyramid(0));
  const RotationAnalysis a = analyse_rotation(in, kUncertainty);
  // Move one side plane by 1e-7 m (a tilt of its normal by 1e-7 rad as well):
  // the apex splits into two corners 1e-7 apart (above the merge distance)
  // or stays one; either way verdicts hold or are marginal, and the margins
  // move by no more than ~1e-6 rad.
  std::vector<Side> s = pyramid(0);
  s[2].inward += Vector3d(0, 1e-7, 0);
  s[2].point += Vector3d(1e-7, 0, 0);
  const RotationInput pin = test_rotation::convex_block("pyramid", s);
  const RotationAnalysis pa = analyse_rotation(pin, kUncertainty);
  for (const auto& c : a.corners) {
    // The nearest static point of the perturbed block.
    const CornerRotation* best = nullptr;
    double dist = 1e300;
    for (const auto& pc : pa.corners) {
      const double d = (pin.vertices[pc.vertex] - in.vertices[c.vertex]).norm();
      if (d < dist) {
        dist = d;
        best = &pc;
      }
    }
    ASSERT_NE(best, nullptr);
    ASSERT_LT(dist, 1e-5);
    EXPECT_TRUE(best->rotatable.value == c.rotatable.value || best->rotatable.marginal ||
                c.rotatable.marginal);
    // Limit planes turn by about perturbation / lever arm (~1e-7 rad);
    // 1e-5 rad leaves room for the split apex's short edge.
    EXPECT_NEAR(best->signed_margin, c.signed_margin, 1e-5);
  }
}

TEST(RotationHardCases, CornersOnFreeFacesOnlyConstrainNothing) {
  // A unit cube standing on the joint z = 0, all other faces free: its top
  // corners touch no joint.
  const std::vector<Side> cube = {
      {"J", true, {0, 0, 1}, {0, 0, 0}},   {"F1", false, {0, 0, -1}, {0, 0, 1}},
      {"F2", false, {1, 0, 0}, {0, 0, 0}}, {"F3", false, {-1, 0, 0}, {1, 0, 0}},
      {"F4", false, {0, 1, 0}, {0, 0, 0}}, {"F5", false, {0, -1, 0}, {0, 1, 0}}};
  const RotationInput in = test_rotation::convex_block("cube", cube);
  const RotationAnalysis a = analyse_rotation(in, kUncertainty);
  ASSERT_EQ(a.corners.size(), 4u);  // the bottom corners only
  ASSERT_EQ(a.edges.size(), 4u);    // the bottom edges only
  for (const auto& c : a.corners) {
    EXPECT_EQ(in.vertices[c.vertex].z(), 0);
    for (const auto& l : c.limits) EXPECT_EQ(in.vertices[l.corner].z(), 0);  // no top corner
  }
  // By hand at R = (0,0,0): (1,0,0) x z = (0,-1,0), (0,1,0) x z = (1,0,0),
  // (1,1,0) x z = (1,-1,0): the wedge {u_x >= 0, u_y <= 0}, margin exactly
  // 45 degrees, its edge the vertical line (both senses).
  const CornerRotation& o = corner(a, test_rotation::corner_at(in, {0, 0, 0}));
  EXPECT_NEAR(rad_to_deg(o.signed_margin), 45, 1e-10);  // exact cone margin, rounding only
  ASSERT_EQ(o.extreme_rays.size(), 2u);
  for (const auto& r : o.extreme_rays) EXPECT_NEAR(std::abs(r.z()), 1, 1e-12);
  // Spinning about the vertical through R slides on the floor: every limit
  // plane comes from the floor itself, so nothing else constrains it.
  ASSERT_EQ(o.sliding.size(), 1u);
  EXPECT_TRUE(o.sliding[0].feasible.value);
  EXPECT_NEAR(o.sliding[0].signed_margin, kPi / 2, 1e-12);
  // Tipping over a bottom edge: about (0,0,0) -> (1,0,0), u = +x: limit
  // planes (1,0,0) and (1,-1,0)/sqrt2 from the far corners: margin 45.
  for (const auto& e : a.edges) {
    EXPECT_TRUE(e.rotatable.value);
    EXPECT_NEAR(rad_to_deg(e.signed_margin), 45, 1e-10);
  }
}

TEST(RotationHardCases, RigidMotionSurveyCoordinatesAndScale) {
  // Tetrahedron T1 of the core tests, from its half-spaces.
  const std::vector<Side> t1 = {{"J1", true, {2, -1, 8}, {0, 0, 0}},
                                {"J2", true, {-1, 16, -4}, {0, 0, 0}},
                                {"J3", true, {15, 8, -2}, {0, 0, 0}},
                                {"F1", false, {-9, -11, -5}, {0, 1, 4}}};
  const RotationInput base = test_rotation::convex_block("T1", t1);
  const RotationAnalysis a = analyse_rotation(base, kUncertainty);
  const Eigen::Matrix3d q =
      Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vector3d datum(512340.0, 5211870.0, 410.0);  // survey coordinates
  for (double scale : {1e-3, 1.0, 100.0}) {
    std::vector<Side> moved = t1;
    for (auto& s : moved) {
      s.inward = q * s.inward;
      s.point = datum + scale * (q * s.point);
    }
    const blocks::Polyhedron poly = test_rotation::convex_polyhedron("T1", moved, datum);
    const RotationInput in = rotation_input(poly);
    const RotationAnalysis b = analyse_rotation(in, kUncertainty);
    ASSERT_EQ(b.corners.size(), a.corners.size());
    for (const auto& c : a.corners) {
      const int v = test_rotation::corner_at(in, scale * (q * base.vertices[c.vertex]));
      const CornerRotation& m = corner(b, v);
      EXPECT_EQ(m.rotatable.value, c.rotatable.value);
      // Datum-relative corners carry ~1e-16 x size error whatever the datum;
      // margins agree to rounding amplified by the cone's conditioning.
      EXPECT_NEAR(m.signed_margin, c.signed_margin, 1e-9) << "scale " << scale;
    }
    ASSERT_EQ(b.edges.size(), a.edges.size());
    for (const auto& e : a.edges) {
      const int v0 = test_rotation::corner_at(in, scale * (q * base.vertices[e.vertices[0]]));
      const int v1 = test_rotation::corner_at(in, scale * (q * base.vertices[e.vertices[1]]));
      const auto m = std::find_if(b.edges.begin(), b.edges.end(), [&](const EdgeRotation& x) {
        return x.vertices == std::array<int, 2>{std::min(v0, v1), std::max(v0, v1)};
      });
      ASSERT_NE(m, b.edges.end());
      EXPECT_EQ(m->rotatable.value, e.rotatable.value);
      EXPECT_NEAR(m->signed_margin, e.signed_margin, 1e-9) << "scale " << scale;
      EXPECT_LT((m->axis - q * e.axis).norm(), 1e-9);  // the sense turns with the block
    }
  }
}

}  // namespace
}  // namespace rockface::kinematics
