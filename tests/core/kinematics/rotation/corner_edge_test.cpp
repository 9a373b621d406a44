// Corner and edge rotatability of tetrahedra worked out by hand: three
// joints J1 = ABD, J2 = ABE, J3 = ADE through the apex A and the free face
// F1 = BDE. The limit planes below are (C - R) x n for every corner C != R
// and every joint through C (n the block-side normal, any length), reduced
// to integers; each is checked against the code, and each verdict is backed
// by a certificate computed here from the hand list alone: an axis strictly
// inside every limit half-space (non-empty), or non-negative weights that
// sum the limit normals to zero (empty, by Gordan's theorem).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/geometry/tolerances.h"
#include "core/kinematics/rotation_space.h"
#include "tests/support/rotation_blocks.h"

namespace rockface::kinematics {
namespace {

using Eigen::Vector3d;
using test_rotation::tetrahedron;

constexpr double kUncertainty = deg_to_rad(1.0);

struct HandLimit {
  int corner;  // 0 A, 1 B, 2 D, 3 E
  std::string joint;
  Vector3d normal;  // integer, not normalised
};

// The code's limit planes of static point `r` equal the hand list (same
// corners, joints and directions, nothing more).
void expect_limits(const RotationInput& in, const CornerRotation& c,
                   const std::vector<HandLimit>& hand) {
  ASSERT_EQ(c.limits.size(), hand.size());
  for (const auto& h : hand) {
    const auto it = std::find_if(c.limits.begin(), c.limits.end(), [&](const LimitPlane& l) {
      return l.corner == h.corner && in.planes[l.plane].name == h.joint;
    });
    ASSERT_NE(it, c.limits.end()) << "corner " << h.corner << " joint " << h.joint;
    // Unit normals from integer vectors: agreement to rounding (~1e-15).
    EXPECT_LT((it->normal - h.normal.normalized()).norm(), 1e-12)
        << "corner " << h.corner << " joint " << h.joint;
  }
}

// min over the hand limit planes of asin(n . u): the axis's margin.
double hand_margin(const std::vector<HandLimit>& hand, const Vector3d& u) {
  double m = kPi / 2;
  for (const auto& h : hand) m = std::min(m, std::asin(h.normal.normalized().dot(u.normalized())));
  return m;
}

// Tetrahedron T1: A = (0,0,0), B = (4,0,-1), D = (-2,4,1), E = (0,1,4).
// Block-side normals: J1 (ABD) = (2,-1,8), J2 (ABE) = (-1,16,-4),
// J3 (ADE) = (15,8,-2) (free face F1 (BDE) = (-9,-11,-5) constrains nothing).
RotationInput t1() {
  return tetrahedron("T1", {0, 0, 0}, {4, 0, -1}, {-2, 4, 1}, {0, 1, 4});
}

TEST(CornerRotation, TetrahedronLimitPlanesAndVerdictsByHand) {
  const RotationInput in = t1();
  // R = B: C - R is A - B = (-4,0,1), D - B = (-6,4,2), E - B = (-4,1,5).
  //   (A-B) x J1 = (-4,0,1) x (2,-1,8) = (0*8-1*(-1), 1*2-(-4)*8, (-4)(-1)-0*2) = (1,34,4)
  const std::vector<HandLimit> at_b = {{0, "J1", {1, 34, 4}},    {0, "J2", {-16, -17, -64}},
                                       {0, "J3", {-8, 7, -32}},  {2, "J1", {17, 26, -1}},
                                       {2, "J3", {-4, 3, -18}},  {3, "J2", {-4, -1, -3}},
                                       {3, "J3", {-42, 67, -47}}};
  // R = D: A - D = (2,-4,-1), B - D = (6,-4,-2), E - D = (2,-3,3).
  //   (A-D) x J1 = (2,-4,-1) x (2,-1,8) = (-32-1, -2-16, -2+8) = (-33,-18,6) = 3 (-11,-6,2)
  const std::vector<HandLimit> at_d = {{0, "J1", {-11, -6, 2}},  {0, "J2", {32, 9, 28}},
                                       {0, "J3", {16, -11, 76}}, {1, "J1", {-17, -26, 1}},
                                       {1, "J2", {24, 13, 46}},  {3, "J2", {-36, 5, 29}},
                                       {3, "J3", {-18, 49, 61}}};
  // R = E: A - E = (0,-1,-4), B - E = (4,-1,-5), D - E = (-2,3,-3).
  //   (A-E) x J1 = (0,-1,-4) x (2,-1,8) = (-8-4, -8-0, 0+2) = (-12,-8,2) = 2 (-6,-4,1)
  const std::vector<HandLimit> at_e = {{0, "J1", {-6, -4, 1}},   {0, "J2", {68, 4, -1}},
                                       {0, "J3", {34, -60, 15}}, {1, "J1", {-13, -42, -2}},
                                       {1, "J2", {4, 1, 3}},     {2, "J1", {21, 10, -4}},
                                       {2, "J3", {18, -49, -61}}};
  // Witness axes, strictly inside every limit half-space (dot products all
  // positive: B 29 63 47 10 25 6 156, D 10 47 163 28 79 53 73, E 2 60 154 71 2 1 116).
  const std::map<int, std::pair<const std::vector<HandLimit>*, Vector3d>> cases = {
      {1, {&at_b, {-1, 1, -1}}}, {2, {&at_d, {0, -1, 2}}}, {3, {&at_e, {1, -2, 0}}}};

  const RotationAnalysis r = analyse_rotation(in, kUncertainty);
  ASSERT_EQ(r.corners.size(), 3u);  // B, D, E; the apex A touches no free face
  for (const auto& c : r.corners) {
    SCOPED_TRACE("corner " + std::to_string(c.vertex));
    const auto& [hand, witness] = cases.at(c.vertex);
    expect_limits(in, c, *hand);
    for (const auto& h : *hand) EXPECT_GT(h.normal.dot(witness), 0);
    EXPECT_TRUE(c.rotatable.value);
    // The exact max-min margin is at least the witness's, and the code's
    // best axis achieves its margin on the hand limit planes (rounding only).
    EXPECT_GE(c.signed_margin, hand_margin(*hand, witness) - 1e-12);
    EXPECT_NEAR(hand_margin(*hand, c.best_axis), c.signed_margin, 1e-12);
    // Every extreme ray lies in the space and on two limit planes.
    ASSERT_GE(c.extreme_rays.size(), 3u);
    for (const auto& ray : c.extreme_rays) {
      EXPECT_GE(hand_margin(*hand, ray), -1e-12);  // inside, to rounding
      int tight = 0;
      for (const auto& h : *hand) tight += std::abs(h.normal.normalized().dot(ray)) < 1e-12;
      EXPECT_GE(tight, 2);
    }
  }
  // Margins of B and D are large (> 10 deg), E's is small but outside the
  // 1 degree uncertainty (the witness alone gives 1.09 degrees).
  EXPECT_GT(rad_to_deg(r.corners[0].signed_margin), 10);
  EXPECT_GT(rad_to_deg(r.corners[1].signed_margin), 10);
  EXPECT_FALSE(r.corners[2].rotatable.marginal);
}

TEST(CornerRotation, TetrahedronSlidingRotationByHand) {
  const RotationInput in = t1();
  const RotationAnalysis r = analyse_rotation(in, kUncertainty);
  // At B, rotation about n_J2 = (-1,16,-4) (J2 = ABE through B): against the
  // limit planes of B not on J2 - (1,34,4) 527, (-8,7,-32) 248,
  // (17,26,-1) 403, (-4,3,-18) 124, (-42,67,-47) 1302 - all positive: the
  // block can rotate about B while sliding on J2. About n_J1 = (2,-1,8):
  // (-16,-17,-64).n_J1 = -32+17-512 < 0: not on J1.
  const CornerRotation& b = r.corners[0];
  ASSERT_EQ(b.vertex, 1);
  ASSERT_EQ(b.sliding.size(), 2u);  // J1 and J2 pass through B
  for (const auto& s : b.sliding) {
    const std::string name = in.planes[s.plane].name;
    if (name == "J2") {
      EXPECT_TRUE(s.feasible.value);
      // The tightest of those: (-4,3,-18).n = 124 / (|(-4,3,-18)| |n_J2|).
      const double expect =
          std::asin(124 / (Vector3d(-4, 3, -18).norm() * Vector3d(-1, 16, -4).norm()));
      EXPECT_NEAR(s.signed_margin, expect, 1e-12);  // same formula, rounding only
    } else {
      EXPECT_EQ(name, "J1");
      EXPECT_FALSE(s.feasible.value);
    }
    EXPECT_TRUE(s.also_sliding.empty());  // no joint of T1 is parallel to another
  }
}

TEST(EdgeRotation, TetrahedronEdgesByHandWithTheirSense) {
  const RotationInput in = t1();
  const RotationAnalysis r = analyse_rotation(in, kUncertainty);
  ASSERT_EQ(r.edges.size(), 3u);  // BD, BE, DE: the free face's rim
  for (const auto& e : r.edges) {
    SCOPED_TRACE(std::to_string(e.vertices[0]) + "-" + std::to_string(e.vertices[1]));
    if (e.vertices == std::array<int, 2>{2, 3}) {
      // About D -> E = (2,-3,3): the limit planes of D from A and B (E is on
      // the axis): (-11,-6,2) 2, (32,9,28) 121, (16,-11,76) 293,
      // (-17,-26,1) 47, (24,13,46) 147: all positive in the sense D -> E;
      // the reverse sense fails on every one of them.
      EXPECT_TRUE(e.rotatable.value);
      EXPECT_GT(e.axis.dot(Vector3d(2, -3, 3)), 0);
      const double expect =
          std::asin(2 / (Vector3d(-11, -6, 2).norm() * Vector3d(2, -3, 3).norm()));
      EXPECT_NEAR(e.signed_margin, expect, 1e-12);  // 1.93 deg, rounding only
      EXPECT_FALSE(e.rotatable.marginal);           // outside the 1 degree uncertainty
    } else {
      // About B -> D = (-6,4,2): (-16,-17,-64) from A gives 96-68-128 < 0 and
      // (1,34,4) gives -6+136+8 > 0, so neither sense is feasible; about
      // B -> E = (-4,1,5): (1,34,4) 50 but (-16,-17,-64) -273, and the
      // reverse sense fails on (1,34,4).
      EXPECT_FALSE(e.rotatable.value);
      EXPECT_FALSE(e.rotatable.marginal);
    }
  }
}

TEST(CornerRotation, TetrahedronWithShutCornerHasGordanCertificate) {
  // Tetrahedron T2: A = (0,0,0), B = (4,-1,1), D = (-1,4,1), E = (1,1,3).
  const RotationInput in = tetrahedron("T2", {0, 0, 0}, {4, -1, 1}, {-1, 4, 1}, {1, 1, 3});
  const RotationAnalysis r = analyse_rotation(in, kUncertainty);
  ASSERT_EQ(r.corners.size(), 3u);
  // At E the limit planes from the apex A are (A - E) x n with A - E = (-1,-1,-3):
  // J1 = (-1,-1,3): (-1,-1,-3) x (-1,-1,3) = (-3-3, 3+3, 1-1) = (-6,6,0) ~ (-1,1,0)
  // J2 = (4,11,-5): (5+33, -12-5, -11+4) = (38,-17,-7)
  // J3 = (11,4,-5): (5+12, -33-5, -4+11) = (17,-38,7)
  // and 55 (-1,1,0) + (38,-17,-7) + (17,-38,7) = 0: no axis is strictly
  // inside all three, the rotation space of E has no interior.
  const Vector3d w1(-1, 1, 0), w2(38, -17, -7), w3(17, -38, 7);
  ASSERT_EQ((55 * w1 + w2 + w3).norm(), 0);
  const CornerRotation& e = r.corners[2];
  ASSERT_EQ(e.vertex, 3);
  for (const Vector3d& w : {w1, w2, w3}) {
    const bool present = std::any_of(e.limits.begin(), e.limits.end(), [&](const LimitPlane& l) {
      return l.corner == 0 && (l.normal - w.normalized()).norm() < 1e-12;
    });
    EXPECT_TRUE(present);
  }
  EXPECT_FALSE(e.rotatable.value);
  EXPECT_LT(rad_to_deg(e.signed_margin), -1);  // shut by more than the uncertainty
  EXPECT_TRUE(e.extreme_rays.empty());
  // B and D are rotatable: witnesses (1,1,-2) and (-1,-1,2) (by the
  // symmetry x <-> y of T2) are strictly inside all their limit planes.
  EXPECT_TRUE(r.corners[0].rotatable.value);
  EXPECT_TRUE(r.corners[1].rotatable.value);
  EXPECT_NEAR(r.corners[0].signed_margin, r.corners[1].signed_margin, 1e-12);  // mirror images
}

TEST(CornerRotation, PolyhedronAdapterGivesTheSameAnswers) {
  // T1 again, built from its four half-spaces by core/blocks.
  const std::vector<test_rotation::Side> sides = {{"J1", true, {2, -1, 8}, {0, 0, 0}},
                                                  {"J2", true, {-1, 16, -4}, {0, 0, 0}},
                                                  {"J3", true, {15, 8, -2}, {0, 0, 0}},
                                                  {"F1", false, {-9, -11, -5}, {0, 1, 4}}};
  const RotationInput built = test_rotation::convex_block("T1", sides);
  const RotationInput hand = t1();
  const RotationAnalysis a = analyse_rotation(built, kUncertainty);
  const RotationAnalysis b = analyse_rotation(hand, kUncertainty);
  ASSERT_EQ(a.corners.size(), b.corners.size());
  for (const auto& cb : b.corners) {
    const int v = test_rotation::corner_at(built, hand.vertices[cb.vertex]);
    const auto ca = std::find_if(a.corners.begin(), a.corners.end(),
                                 [&](const CornerRotation& c) { return c.vertex == v; });
    ASSERT_NE(ca, a.corners.end());
    EXPECT_EQ(ca->rotatable.value, cb.rotatable.value);
    // Corners from plane intersections agree with the integer ones to ~1e-15.
    EXPECT_NEAR(ca->signed_margin, cb.signed_margin, 1e-9);
  }
}

}  // namespace
}  // namespace rockface::kinematics

namespace rockface::kinematics {
namespace {

TEST(CornerRotation, SpinBetweenTwoParallelJointsSlidesOnBoth) {
  // A unit cube between a joint floor z = 0 and a joint roof z = 1 (block
  // below it), sides free. At R = (0,0,0) the floor corners give u_y <= 0,
  // u_x >= 0, u_x - u_y >= 0 and the roof corners u_y >= 0, u_x <= 0,
  // -u_x + u_y >= 0 (the roof corner straight above R is void): only the
  // vertical line is left - no interior, so not corner-rotatable (margin 0,
  // marginal) - but spinning about the floor's normal +z slides on the floor
  // and keeps the roof in sliding contact too.
  const std::vector<test_rotation::Side> cube = {
      {"Jfloor", true, {0, 0, 1}, {0, 0, 0}}, {"Jroof", true, {0, 0, -1}, {0, 0, 1}},
      {"F2", false, {1, 0, 0}, {0, 0, 0}},    {"F3", false, {-1, 0, 0}, {1, 0, 0}},
      {"F4", false, {0, 1, 0}, {0, 0, 0}},    {"F5", false, {0, -1, 0}, {0, 1, 0}}};
  const RotationInput in = test_rotation::convex_block("slab", cube);
  const RotationTopology t = rotation_topology(in);
  const int r = test_rotation::corner_at(in, {0, 0, 0});
  const CornerRotation c = corner_rotation(in, t, r, kUncertainty);
  EXPECT_EQ(c.void_limits, 1);  // the roof corner (0,0,1)
  EXPECT_FALSE(c.rotatable.value);
  EXPECT_TRUE(c.rotatable.marginal);
  EXPECT_NEAR(c.signed_margin, 0, 1e-12);  // a line: margin zero to rounding
  ASSERT_EQ(c.sliding.size(), 1u);         // only the floor passes through R
  const SlidingRotation& s = c.sliding[0];
  EXPECT_EQ(in.planes[s.plane].name, "Jfloor");
  EXPECT_TRUE(s.feasible.value);
  EXPECT_NEAR(s.signed_margin, kPi / 2, 1e-12);  // nothing else constrains the spin
  ASSERT_EQ(s.also_sliding.size(), 1u);
  EXPECT_EQ(in.planes[s.also_sliding[0]].name, "Jroof");
}

}  // namespace
}  // namespace rockface::kinematics

namespace rockface::kinematics {
namespace {

// The remote-axis skip rule (issue 17): only a firm verdict (true and not
// marginal) gives an axis; a corner is preferred to an edge.
TEST(FirmAxis, OnlyFirmVerdictsGiveAnAxisAndCornersComeFirst) {
  kinematics::RotationAnalysis a;
  EXPECT_FALSE(kinematics::firm_corner_or_edge_axis(a).has_value());

  kinematics::CornerRotation marginal_corner;
  marginal_corner.vertex = 2;
  marginal_corner.rotatable.value = true;
  marginal_corner.rotatable.marginal = true;
  kinematics::CornerRotation shut_corner;
  shut_corner.vertex = 3;
  shut_corner.rotatable.value = false;
  a.corners = {marginal_corner, shut_corner};
  kinematics::EdgeRotation edge;
  edge.vertices = {1, 4};
  edge.axis = Eigen::Vector3d::UnitX();
  edge.rotatable.value = true;
  a.edges = {edge};
  auto firm = kinematics::firm_corner_or_edge_axis(a);
  ASSERT_TRUE(firm.has_value());
  EXPECT_FALSE(firm->about_corner);
  EXPECT_EQ(firm->edge, (std::array<int, 2>{1, 4}));
  EXPECT_EQ(firm->vertex, 1);
  EXPECT_EQ(firm->direction, Eigen::Vector3d::UnitX());

  kinematics::CornerRotation firm_corner;
  firm_corner.vertex = 5;
  firm_corner.rotatable.value = true;
  firm_corner.best_axis = Eigen::Vector3d::UnitY();
  a.corners.push_back(firm_corner);
  firm = kinematics::firm_corner_or_edge_axis(a);
  ASSERT_TRUE(firm.has_value());
  EXPECT_TRUE(firm->about_corner);
  EXPECT_EQ(firm->vertex, 5);
  EXPECT_EQ(firm->direction, Eigen::Vector3d::UnitY());

  a.edges[0].rotatable.marginal = true;
  a.corners.pop_back();
  EXPECT_FALSE(kinematics::firm_corner_or_edge_axis(a).has_value());
}

}  // namespace
}  // namespace rockface::kinematics
