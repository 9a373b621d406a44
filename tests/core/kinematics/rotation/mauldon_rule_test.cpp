// Mauldon's rule, checked on many blocks: if the joint pyramid JP(C) of a
// corner C (the directions C can move in without entering the rock behind
// its joints) meets the plane across C - R only at the origin, then C cannot
// move perpendicular to its lever arm about R: the only axes left through R
// are along C - R, so the rotation space of R has no interior (not
// corner-rotatable), and rotation about any edge through R other than RC
// moves C into the rock (not edge-rotatable). JP(C) misses that plane
// exactly when every extreme ray e of JP(C) has e . (R - C) > 0.
//
// The rule is computed here from the joint pyramids alone (geometry::Cone
// of the joints at C), independently of the limit planes, and must never
// contradict the code's verdicts.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/geometry/cone.h"
#include "core/kinematics/rotation_space.h"
#include "tests/support/rotation_blocks.h"

namespace rockface::kinematics {
namespace {

using Eigen::Vector3d;

constexpr double kUncertainty = deg_to_rad(1.0);

// Whether JP(C) is non-rotatable about R, with a clear margin (every extreme
// ray at least 1e-6 rad on the far side of the plane across C - R).
bool jp_non_rotatable(const RotationInput& in, const RotationTopology& t, int c, int r) {
  std::vector<Vector3d> joints;
  for (int p : t.vertex_planes[c])
    if (in.planes[p].joint) joints.push_back(in.planes[p].inward_normal);
  if (joints.size() < 3) return false;  // a half-space or wedge always meets the plane
  const geometry::Cone jp(joints);
  const auto rays = jp.edges();
  if (rays.size() < 3) return false;
  const Vector3d arm = (in.vertices[r] - in.vertices[c]).normalized();
  for (const auto& e : rays)
    if (!(e.dot(arm) > 1e-6)) return false;
  return true;
}

struct RuleCount {
  int corners = 0, edges = 0;
};

RuleCount check_rule(const RotationInput& in) {
  RuleCount count;
  const RotationTopology t = rotation_topology(in);
  const RotationAnalysis a = analyse_rotation(in, kUncertainty);
  for (const auto& corner : a.corners) {
    const int r = corner.vertex;
    for (int c = 0; c < static_cast<int>(in.vertices.size()); ++c) {
      if (c == r || !jp_non_rotatable(in, t, c, r)) continue;
      ++count.corners;
      // No interior: at best the single axis along C - R, margin <= 0 (to
      // rounding of the cone margin, ~1e-15).
      EXPECT_LE(corner.signed_margin, 1e-12) << in.block << " R " << r << " C " << c;
      EXPECT_FALSE(corner.rotatable.value) << in.block << " R " << r << " C " << c;
      for (const auto& edge : a.edges) {
        if (edge.vertices[0] != r && edge.vertices[1] != r) continue;
        if (edge.vertices[0] == c || edge.vertices[1] == c) continue;  // C on the axis
        ++count.edges;
        EXPECT_FALSE(edge.rotatable.value) << in.block << " R " << r << " C " << c;
      }
    }
  }
  return count;
}

// A convex block cut from random planes tangent to a sphere: the first
// `free` of them are free faces. Returns false when the planes leave it
// unbounded.
bool random_block(std::mt19937& gen, int planes, int free, RotationInput& out) {
  auto uniform = [&] { return (static_cast<double>(gen()) + 0.5) / 4294967296.0; };
  std::vector<test_rotation::Side> sides;
  for (int i = 0; i < planes; ++i) {
    const double z = 2 * uniform() - 1, phi = 2 * kPi * uniform();
    const Vector3d n(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    const double reach = 0.6 + 0.8 * uniform();  // distance of the plane from the centre
    sides.push_back({(i < free ? "F" : "J") + std::to_string(i), i >= free, -n, reach * n});
  }
  try {
    out = test_rotation::convex_block("random", sides);
    return true;
  } catch (const std::runtime_error&) {
    return false;
  }
}

TEST(MauldonRule, HoldsOnTetrahedra) {
  RuleCount total;
  auto add = [&](const RotationInput& in) {
    const RuleCount c = check_rule(in);
    total.corners += c.corners;
    total.edges += c.edges;
  };
  // The acute-apex tetrahedron: the apex's joint pyramid (its three edges
  // AB, AD, AE all make acute angles with each other) is non-rotatable
  // about every free-face corner.
  add(test_rotation::tetrahedron("T0", {0, 0, 0}, {4, 1, 0}, {1, 4, 1}, {0, 1, 4}));
  add(test_rotation::tetrahedron("T1", {0, 0, 0}, {4, 0, -1}, {-2, 4, 1}, {0, 1, 4}));
  add(test_rotation::tetrahedron("T2", {0, 0, 0}, {4, -1, 1}, {-1, 4, 1}, {1, 1, 3}));
  // T0: the rule decides all three static points, and their six rim edges
  // (two per static point, each with the apex off its axis).
  EXPECT_GE(total.corners, 3);
  EXPECT_GE(total.edges, 6);
}

TEST(MauldonRule, HoldsOnRandomConvexBlocks) {
  std::mt19937 gen(20261121);
  RuleCount total;
  int blocks = 0;
  for (int trial = 0; trial < 400 && blocks < 120; ++trial) {
    RotationInput in;
    const int planes = 5 + trial % 6;  // 5 .. 10 planes
    if (!random_block(gen, planes, 1 + trial % 2, in)) continue;
    ++blocks;
    const RuleCount c = check_rule(in);
    total.corners += c.corners;
    total.edges += c.edges;
  }
  EXPECT_GE(blocks, 100);
  // The rule must have had something to decide (it applies on a good share
  // of random blocks: counted here so that the test cannot pass vacuously).
  EXPECT_GT(total.corners, 20);
  EXPECT_GT(total.edges, 20);
  RecordProperty("rule_applications", std::to_string(total.corners) + " corners, " +
                                          std::to_string(total.edges) + " edges");
}

}  // namespace
}  // namespace rockface::kinematics

namespace rockface::kinematics {
namespace {

TEST(CornerRotation, ActiveSetMarginEqualsTheDirectConeSearchOnLargeBlocks) {
  // Blocks with 12 to 16 faces have 40-80 limit planes per static point:
  // the margin comes from the active-set search; it must equal
  // geometry::Cone's direct search over all of them.
  std::mt19937 gen(4242);
  int compared = 0, shut = 0, open = 0;
  for (int trial = 0; trial < 60 && compared < 40; ++trial) {
    RotationInput in;
    // Up to 8 free faces: corners with few joints, so some spaces open.
    if (!random_block(gen, 12 + trial % 5, 2 + trial % 7, in)) continue;
    const RotationAnalysis a = analyse_rotation(in, kUncertainty);
    for (const auto& c : a.corners) {
      if (c.limits.size() <= 12) continue;
      ++compared;
      (c.signed_margin > 0 ? open : shut) += 1;
      // Both exact; they differ by rounding of dot products (~1e-15).
      EXPECT_NEAR(c.signed_margin, c.space.margin().angle, 1e-12);
      EXPECT_NEAR(c.space.margin_of(c.best_axis), c.signed_margin, 1e-12);
    }
  }
  EXPECT_GE(compared, 40);
  EXPECT_GT(open, 0);  // both kinds of verdict were compared
  EXPECT_GT(shut, 0);
}

}  // namespace
}  // namespace rockface::kinematics
