// The tunnel-crown experiment: a keyblock over a horizontal tunnel roof
// (free face z = 0, rock above), bounded by four steep joints dipping
// theta = 75 degrees toward N, E, S and W through the sides of a 2a x 2a
// square on the roof, so that it tapers upward, and cut by a flat joint at
// height h. The joint pyramid is the same for every h (same five joint
// orientations; it holds the vertical, the block can fall). Rotatability
// is not:
//
// Take the static point R = the SW roof corner (-a,-a,0) and the tipping
// axis u = (-1,1,0)/sqrt2 through it (horizontal, across the diagonal): the
// far side drops. A corner at C - R = (X,Y,Z) moves along
// u x (C - R) = (Z, Z, -(X + Y)) / sqrt2, so the roof corners stay on the
// roof, the flat joint's corners go down (away from it), and the top
// corners move out by Z = h horizontally while dropping by X + Y. The
// tightest of them is the top NW corner (-b, b, h), b = a - h cot(theta),
// on the north joint (block-side normal -(0, sin theta, cos theta)):
//   (h, h, -2a) . -(0, sin, cos) / sqrt2 = (2a cos theta - h sin theta) / sqrt2,
// non-negative exactly when h <= h* = 2a cot(theta) (the SE top corner on the
// east joint gives the same by symmetry). Above h*, the limit planes of
// the NW and SE roof corners (on the W and S joints) and of the NW and SE
// top corners (on the N and E joints) together shut the rotation space:
// four limit half-spaces with no common interior.
//
// So: slices cut higher than h* (tall blocks) are not corner-rotatable,
// slices cut lower are, by all four roof corners (the block's symmetry).
#include <cmath>
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

constexpr double kA = 1.0;                   // half width of the roof square, m
constexpr double kTheta = deg_to_rad(75.0);  // dip of the four steep joints
constexpr double kUncertainty = deg_to_rad(1.0);

std::vector<test_rotation::Side> crown_sides(double h) {
  const double s = std::sin(kTheta), c = std::cos(kTheta);
  return {{"F1", false, {0, 0, 1}, {0, 0, 0}},  // the roof: rock above
          {"JN", true, -Vector3d(0, s, c), {0, kA, 0}},
          {"JE", true, -Vector3d(s, 0, c), {kA, 0, 0}},
          {"JS", true, -Vector3d(0, -s, c), {0, -kA, 0}},
          {"JW", true, -Vector3d(-s, 0, c), {-kA, 0, 0}},
          {"JF", true, {0, 0, -1}, {0, 0, h}}};  // the flat joint: block below it
}

// The first-order displacement check written out here, without the code's
// limit planes: every corner on a joint moves to the joint's block side.
double worst_displacement(const RotationInput& in, const Vector3d& pivot, const Vector3d& u) {
  const RotationTopology t = rotation_topology(in);
  double worst = 1e300;
  for (size_t v = 0; v < in.vertices.size(); ++v)
    for (int p : t.vertex_planes[v])
      if (in.planes[p].joint)
        worst = std::min(worst, u.cross(in.vertices[v] - pivot).dot(in.planes[p].inward_normal));
  return worst;
}

TEST(TunnelCrown, SameJointPyramidRotatableOnlyBelowTheCriticalCut) {
  const double h_star = 2 * kA / std::tan(kTheta);  // 0.536 m
  const Vector3d r_sw(-kA, -kA, 0);
  const Vector3d tip = Vector3d(-1, 1, 0).normalized();
  // From tall (apex at a tan(theta) = 3.73 m) to thin slices.
  const std::vector<double> cuts = {3.0,           2.0, 1.0, 0.7, 1.05 * h_star,
                                    0.95 * h_star, 0.4, 0.2, 0.05};
  double jp_margin = 0;
  for (size_t i = 0; i < cuts.size(); ++i) {
    const double h = cuts[i];
    SCOPED_TRACE("flat joint at h = " + std::to_string(h));
    const RotationInput in = test_rotation::convex_block("crown", crown_sides(h));
    // The joint pyramid of the five joints does not depend on h.
    std::vector<Vector3d> joints;
    for (const auto& p : in.planes)
      if (p.joint) joints.push_back(p.inward_normal);
    ASSERT_EQ(joints.size(), 5u);
    const double m = geometry::Cone(joints).margin().angle;
    if (i == 0) jp_margin = m;
    EXPECT_NEAR(m, jp_margin, 1e-12);  // same normals every time, rounding only
    EXPECT_GT(m, 0);                   // open: the falling direction is in it

    const RotationAnalysis r = analyse_rotation(in, kUncertainty);
    ASSERT_EQ(r.corners.size(), 4u);  // the roof corners
    const bool low = h < h_star;
    for (const auto& c : r.corners) {
      EXPECT_EQ(c.rotatable.value, low) << "corner " << c.vertex;
      EXPECT_FALSE(c.rotatable.marginal) << "corner " << c.vertex;
    }
    // The hand argument, checked from the displacements alone: the tipping
    // axis through the SW corner is feasible exactly below h*.
    const double worst = worst_displacement(in, r_sw, tip);
    if (low)
      EXPECT_GE(worst, 0);
    else
      EXPECT_LT(worst, 0);
    // The code's verdict at the SW corner agrees and, above h*, the four limit
    // planes named above shut the space on their own.
    const int sw = test_rotation::corner_at(in, r_sw);
    const auto& c_sw = *std::find_if(r.corners.begin(), r.corners.end(),
                                     [&](const CornerRotation& c) { return c.vertex == sw; });
    if (!low) {
      const double b = kA - h / std::tan(kTheta);
      const std::vector<std::pair<Vector3d, std::string>> shut = {
          {{-kA, kA, 0}, "JW"}, {{kA, -kA, 0}, "JS"}, {{-b, b, h}, "JN"}, {{b, -b, h}, "JE"}};
      std::vector<Vector3d> normals;
      for (const auto& [x, joint] : shut) {
        const int v = test_rotation::corner_at(in, x);
        for (const auto& l : c_sw.limits)
          if (l.corner == v && in.planes[l.plane].name == joint) normals.push_back(l.normal);
      }
      ASSERT_EQ(normals.size(), 4u);
      EXPECT_LT(geometry::Cone(normals).margin().angle, 0);
    }
    RecordProperty("h_" + std::to_string(i), std::to_string(h) + " m: corner margin " +
                                                 std::to_string(rad_to_deg(c_sw.signed_margin)) +
                                                 " deg");
  }
}

TEST(TunnelCrown, CriticalCutIsMarginalNotFlipping) {
  // Right at h* the tipping axis only grazes the north joint: the verdict
  // there is marginal (margin inside the uncertainty), and slices just
  // either side give the two verdicts with small margins.
  const double h_star = 2 * kA / std::tan(kTheta);
  for (double f : {0.9995, 1.0, 1.0005}) {
    const RotationInput in = test_rotation::convex_block("crown", crown_sides(f * h_star));
    const RotationAnalysis r = analyse_rotation(in, kUncertainty);
    for (const auto& c : r.corners) {
      EXPECT_TRUE(c.rotatable.marginal) << f;
      EXPECT_LT(std::abs(c.signed_margin), kUncertainty) << f;
    }
  }
}

}  // namespace
}  // namespace rockface::kinematics
