// The check of a support class on this face in closed form: a falling roof
// wedge (the regular tetrahedron of tests/core/tunnel/wedge_analysis_test)
// that the class's pattern holds, and the same wedge under bolts too short
// to reach past it; a block of the face sliding on one plane, with and
// without the class's face bolts; a wedge of the face sliding out of it on
// one plane, held by the class's face bolts or face shotcrete (the wedge
// analysis run with them) and not held without them or with face bolts
// too short. A decision's change applied to the class and the wedge checked
// again: the class's 2 m bolts do not hold the roof wedge and the changed
// 4 m bolts do; a spacing widened from 0.7 m to 1.2 m leaves it flagged.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/analysis/support_changes.h"
#include "core/analysis/support_check.h"
#include "core/geometry/orientation.h"

namespace rockface::analysis {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRad = kPi / 180.0;

// Three sets dipping 60 toward 0, 120, 240: below all three (code 111) a
// regular tetrahedron in the roof of a 6 m square section, base inradius
// r = B / (2 sqrt 3), apex h = r tan 60 above the roof (3 m), weight
// sqrt(3) r^3 tan(60) x 2700 x 9.81 (413 kN). It falls.
struct RoofWedge {
  double B = 6, alpha = 60 * kRad;
  double r() const { return B / (2 * std::sqrt(3.0)); }
  double h() const { return r() * std::tan(alpha); }
  double weight() const {
    return std::sqrt(3.0) * std::pow(r(), 3) * std::tan(alpha) * 2700 * 9.81;
  }
  // Bolts of a square pattern of spacing s from the crown on its base.
  int bolts_on(double s) const { return anchored_on(s, 1e9); }
  // Of those, the bolts of length L that reach past the wedge: a bolt m
  // from the base's nearest edge meets the face dipping alpha above it at
  // the depth m tan(alpha).
  int anchored_on(double s, double L) const {
    int n = 0;
    for (int i = -20; i <= 20; ++i)
      for (int j = -20; j <= 20; ++j) {
        const double x = i * s, y = j * s;
        const double m = std::min({r() - y, r() - (std::sqrt(3.0) / 2 * x - 0.5 * y),
                                   r() - (-std::sqrt(3.0) / 2 * x - 0.5 * y)});
        if (m > 0 && m * std::tan(alpha) < L) ++n;
      }
    return n;
  }
  tunnel::WedgeAnalysis analyse(const SupportClass& c) const {
    std::vector<tunnel::WedgeJointSet> sets;
    for (int i = 0; i < 3; ++i)
      sets.push_back(
          {"J" + std::to_string(i + 1), geometry::plane_normal_deg(60, 120.0 * i), 30 * kRad, 0});
    return tunnel::analyse_wedges(tunnel::rectangle_profile(B, B, 0),
                                  tunnel::axis_frame(0, 0, Eigen::Vector3d::Zero(), "axis"),
                                  Eigen::Vector3d::Zero(), sets, with_class_support({}, c));
  }
};

const tunnel::Wedge& roof_wedge(const tunnel::WedgeAnalysis& a) {
  for (const auto& w : a.wedges)
    if (w.code == "111") return w;
  throw std::runtime_error("no roof wedge 111");
}

SupportClass pattern_class(double length, double spacing, double capacity) {
  SupportClass c;
  c.name = "SC2";
  c.bolts = BoltPattern{length, spacing, capacity, std::nullopt};
  return c;
}

// The sums over bolts and the wedge's volume: rounding, ~1e-12 relative.
constexpr double kSumRel = 1e-9;
// The bisection of the required force stops ~1e-11 N from it (60 halvings
// of 10 MN); relative to forces of ~1e4 N and more.
constexpr double kBisectionRel = 1e-9;

TEST(SupportCheck, APatternThatReachesPastTheApexHoldsTheFallingWedge) {
  const RoofWedge g;
  const int n = g.bolts_on(0.7);
  ASSERT_GT(n, 10);
  // Capacity for a FoS of 2 with every bolt: n C / W = 2.
  const double capacity = 2 * g.weight() / n;
  const SupportClass c = pattern_class(g.h() + 1.5, 0.7, capacity);
  const WedgeSupportCheck w = check_wedge(roof_wedge(g.analyse(c)), c);
  EXPECT_EQ(w.mode, "falling");
  EXPECT_EQ(w.bolts, n);
  EXPECT_EQ(w.bolts_anchored, n);
  EXPECT_TRUE(w.bolts_reach_past_apex);
  ASSERT_TRUE(w.fos_supported);
  EXPECT_NEAR(*w.fos_supported, 2.0, kSumRel * 2);
  EXPECT_FALSE(w.below_target);
  EXPECT_TRUE(w.fixes.empty());
  // Falling, vertical bolts: FoS = n C / W, so the target 1.5 needs
  // C = 1.5 W / n, and the apex depth h plus 1 m of anchorage.
  ASSERT_TRUE(w.required_capacity_n);
  EXPECT_NEAR(*w.required_capacity_n, 1.5 * g.weight() / n, kBisectionRel * g.weight());
  EXPECT_NEAR(w.apex_depth_m, g.h(), kSumRel * g.h());
  EXPECT_NEAR(w.required_bolt_length_m, g.h() + kMinBoltAnchorageM, kSumRel * g.h());
}

TEST(SupportCheck, BoltsTooShortLeaveTheWedgeBelowTheTargetAndSayHowLong) {
  const RoofWedge g;
  const int n = g.bolts_on(0.7);
  const double capacity = 2 * g.weight() / n;  // enough, were they long enough
  const SupportClass c = pattern_class(0.3 * g.h(), 0.7, capacity);
  const WedgeSupportCheck w = check_wedge(roof_wedge(g.analyse(c)), c);
  EXPECT_FALSE(w.bolts_reach_past_apex);
  // Only the bolts near the edges (depth tan(60) x distance to an edge
  // below 0.9 m) are anchored: fewer than three quarters of them, so
  // FoS = 2 anchored / n < 1.5.
  ASSERT_LT(w.bolts_anchored, 0.75 * n);
  ASSERT_TRUE(w.fos_supported);
  EXPECT_NEAR(*w.fos_supported, w.bolts_anchored * capacity / g.weight(), kSumRel);
  EXPECT_TRUE(w.below_target);
  ASSERT_EQ(w.fixes.size(), 1u);  // the length alone: the capacity is enough
  EXPECT_NE(w.fixes[0].find("bolts of at least 4.00 m"), std::string::npos) << w.fixes[0];
  const SupportCheck all = check_support(c, nullptr, {});
  EXPECT_FALSE(all.notes.empty());  // no wedge analysis: said so
}

TEST(SupportCheck, TooWeakBoltsAskForTheirCapacity) {
  const RoofWedge g;
  const int n = g.bolts_on(0.7);
  const SupportClass c = pattern_class(g.h() + 1.5, 0.7, 1.0 * g.weight() / n);  // FoS 1
  const WedgeSupportCheck w = check_wedge(roof_wedge(g.analyse(c)), c);
  EXPECT_TRUE(w.below_target);
  ASSERT_EQ(w.fixes.size(), 1u);
  EXPECT_NE(w.fixes[0].find("kN at 0.70 m spacing"), std::string::npos) << w.fixes[0];
}

// The decision changes the class's 2 m bolts to 4 m: the wedge's apex is
// 3 m deep, so the class's bolts reach past it only within 2 / tan(60) =
// 1.15 m of its base's edges (the anchored count in closed form: 94 % of
// them at 0.7 m), and with a capacity of 1.55 W / n per bolt the class
// leaves it at FoS = 1.55 anchored / n < 1.5, while the changed 4 m bolts
// all anchor and hold it at FoS 1.55.
TEST(SupportCheck, TheDecisionsLongerBoltsHoldTheWedgeTheClassesDoNot) {
  const RoofWedge g;
  const double s = 0.7;
  const int n = g.bolts_on(s), anchored_2m = g.anchored_on(s, 2.0);
  ASSERT_LT(anchored_2m, n);
  const double capacity = 1.55 * g.weight() / n;
  ASSERT_LT(1.55 * anchored_2m / n, 1.5) << "the class's bolts must leave the wedge below 1.5";
  const SupportClass c = pattern_class(2.0, s, capacity);
  const WedgeSupportCheck before = check_wedge(roof_wedge(g.analyse(c)), c);
  EXPECT_EQ(before.bolts, n);
  EXPECT_EQ(before.bolts_anchored, anchored_2m);
  EXPECT_FALSE(before.bolts_reach_past_apex);
  ASSERT_TRUE(before.fos_supported);
  EXPECT_NEAR(*before.fos_supported, 1.55 * anchored_2m / n, kSumRel);
  EXPECT_TRUE(before.below_target);
  ASSERT_FALSE(before.fixes.empty());
  EXPECT_NE(before.fixes[0].find("bolts of at least 4.00 m"), std::string::npos) << before.fixes[0];

  const ChangedPattern changed =
      apply_support_changes(c, {{"bolt length", "2 m", "4 m", "W1's apex is 3 m deep"}}, "test");
  ASSERT_TRUE(changed.pattern.bolts);
  EXPECT_EQ(changed.pattern.bolts->length_m, 4.0);
  EXPECT_EQ(changed.pattern.bolts->spacing_m, s);  // the rest of the class as it was
  EXPECT_EQ(changed.pattern.bolts->capacity_n, capacity);
  const WedgeSupportCheck after =
      check_wedge(roof_wedge(g.analyse(changed.pattern)), changed.pattern);
  EXPECT_EQ(after.bolts_anchored, n);
  EXPECT_TRUE(after.bolts_reach_past_apex);
  ASSERT_TRUE(after.fos_supported);
  EXPECT_NEAR(*after.fos_supported, 1.55, kSumRel * 2);
  EXPECT_FALSE(after.below_target);
  EXPECT_TRUE(after.fixes.empty());
}

// The reverse: the class's 0.7 m pattern of long bolts holds the wedge at
// FoS 2; the decision widens it to 1.2 m, which puts n' = bolts_on(1.2)
// bolts on its base, FoS = 2 n' / n (under 1.5: the wedge is flagged, and
// the capacity per bolt at the wider spacing that would hold it is said).
TEST(SupportCheck, TheDecisionsWiderSpacingLeavesTheWedgeFlagged) {
  const RoofWedge g;
  const int n = g.bolts_on(0.7), wide = g.bolts_on(1.2);
  ASSERT_LT(2.0 * wide / n, 1.5);
  const double capacity = 2 * g.weight() / n;
  const SupportClass c = pattern_class(g.h() + 1.5, 0.7, capacity);
  const WedgeSupportCheck before = check_wedge(roof_wedge(g.analyse(c)), c);
  EXPECT_FALSE(before.below_target);
  const ChangedPattern changed = apply_support_changes(
      c, {{"bolt spacing", "700 mm", "1.2 m", "the jumbo's boom reaches 1.2 m"}}, "test");
  const WedgeSupportCheck after =
      check_wedge(roof_wedge(g.analyse(changed.pattern)), changed.pattern);
  EXPECT_EQ(after.bolts, wide);
  EXPECT_EQ(after.bolts_anchored, wide);
  ASSERT_TRUE(after.fos_supported);
  EXPECT_NEAR(*after.fos_supported, 2.0 * wide / n, kSumRel * 2);
  EXPECT_TRUE(after.below_target);
  // FoS = wide C' / W = 1.5 at C' = 1.5 W / wide.
  ASSERT_TRUE(after.required_capacity_n);
  EXPECT_NEAR(*after.required_capacity_n, 1.5 * g.weight() / wide, kBisectionRel * g.weight());
}

// A block of the face on a plane dipping beta = 50 toward the tunnel (the
// drive runs north, the face looks south, the plane dips to 180), friction
// 30, no cohesion, weight W = 100 kN, 4 m² exposed, 1.5 m deep along the
// drive. Without support FoS = tan(phi) / tan(beta) = 0.484. Bolts of
// total force T along the drive (d = north) press it on its plane and pull
// it back up the dip:
//   FoS = ((W cos(beta) + T sin(beta)) tan(phi) + T cos(beta)) / (W sin(beta)).
struct FaceBlock {
  double beta = 50 * kRad, phi = 30 * kRad, W = 1e5;
  MovingBlock block() const {
    MovingBlock b;
    b.id = "B1";
    const Eigen::Vector3d n(0, -std::sin(beta), std::cos(beta));  // block side: up
    b.loads = Eigen::Vector3d(0, 0, -W);
    b.contacts.push_back({0, n, phi, 0});
    b.mode = kinematics::sliding_mode(b.loads, b.contacts, 0);
    b.fos = b.mode.fos;
    b.exposed_area_m2 = 4;
    b.bolt_direction = Eigen::Vector3d::UnitY();
    b.depth_m = 1.5;
    return b;
  }
  double fos(double T) const {
    return ((W * std::cos(beta) + T * std::sin(beta)) * std::tan(phi) + T * std::cos(beta)) /
           (W * std::sin(beta));
  }
};

TEST(SupportCheck, TheFaceBlockHeldByTheClassesFaceBolts) {
  const FaceBlock g;
  const MovingBlock b = g.block();
  ASSERT_EQ(b.mode.type, kinematics::ModeType::Sliding);
  ASSERT_TRUE(b.fos);
  // sliding_mode's own FoS against the closed form (rounding only).
  EXPECT_NEAR(*b.fos, std::tan(g.phi) / std::tan(g.beta), 1e-12);
  SupportClass c;
  c.name = "SC4";
  c.face.bolts = BoltPattern{4.0, 1.0, 5e4, std::nullopt};  // 4 bolts of 50 kN on 4 m²
  const BlockSupportCheck s = check_block(b, c);
  EXPECT_EQ(s.bolts, 4);
  EXPECT_EQ(s.bolts_anchored, 4);
  ASSERT_TRUE(s.fos_supported);
  // Rounding of the 3x3 decomposition: 1e-12 relative.
  EXPECT_NEAR(*s.fos_supported, g.fos(2e5), 1e-9 * g.fos(2e5));
  EXPECT_FALSE(s.below_target);
  EXPECT_NEAR(s.required_bolt_length_m, 1.5 + kMinBoltAnchorageM, 1e-12);
}

TEST(SupportCheck, TheFaceBlockWithoutFaceSupportIsFlaggedWithTheForceThatHoldsIt) {
  const FaceBlock g;
  SupportClass c;
  c.name = "SC1";
  const BlockSupportCheck s = check_block(g.block(), c);
  ASSERT_TRUE(s.fos_supported);
  EXPECT_NEAR(*s.fos_supported, g.fos(0), 1e-12);
  EXPECT_TRUE(s.below_target);
  // The total T with FoS(T) = 1.5, solved from the closed form (linear in T).
  const double a = std::sin(g.beta) * std::tan(g.phi) + std::cos(g.beta);
  const double T = (1.5 * g.W * std::sin(g.beta) - g.W * std::cos(g.beta) * std::tan(g.phi)) / a;
  ASSERT_TRUE(s.required_face_force_n);
  EXPECT_NEAR(*s.required_face_force_n, T, kBisectionRel * T);
  ASSERT_EQ(s.fixes.size(), 1u);
  EXPECT_NE(s.fixes[0].find("the class has none"), std::string::npos) << s.fixes[0];
  // Face bolts shorter than the block is deep hold nothing.
  c.face.bolts = BoltPattern{1.2, 1.0, 5e4, std::nullopt};
  const BlockSupportCheck short_bolts = check_block(g.block(), c);
  EXPECT_EQ(short_bolts.bolts_anchored, 0);
  EXPECT_TRUE(short_bolts.below_target);
  ASSERT_FALSE(short_bolts.fixes.empty());
  EXPECT_NE(short_bolts.fixes[0].find("2.50 m"), std::string::npos) << short_bolts.fixes[0];
}

// Three sets whose pyramid opens back out of the face of a 6 m square
// section driven north: J1 dips beta = 60 toward the tunnel (south) under
// the wedge, J2 and J3 are J1 turned +-120 degrees about the drive and
// close it above. On the face they cut an equilateral triangle (J1's
// trace horizontal), the largest of which in the section has side 6 m; the
// apex lies r / tan(beta) = 1 m ahead of the face (r: the triangle's
// inradius). The wedge slides out of the face on J1 alone (J2 and J3 open
// along J1's dip) with FoS = tan(phi) / tan(beta) = 0.333 for phi = 30.
// Face bolts along the drive with total force T and a face lining of
// capacity P (against the motion) give, as for the face block above,
//   FoS = ((W cos(beta) + T sin(beta)) tan(phi) + T cos(beta) + P) / (W sin(beta)).
struct FaceWedge {
  double B = 6, beta = 60 * kRad, phi = 30 * kRad;
  tunnel::WedgeAnalysis analyse(const tunnel::WedgeOptions& o) const {
    const Eigen::Vector3d j1(0, -std::sin(beta), std::cos(beta));  // upward normal
    std::vector<tunnel::WedgeJointSet> sets{{"J1", j1, phi, 0}};
    for (const double turn : {120.0, -120.0}) {
      const double t = turn * kRad;
      // J1's block-side normal (= j1) turned about the drive, then upward.
      const Eigen::Vector3d n(std::cos(beta) * std::sin(t), -std::sin(beta),
                              std::cos(beta) * std::cos(t));
      sets.push_back({"J" + std::to_string(sets.size() + 1), -n, phi, 0});
    }
    return tunnel::analyse_wedges(tunnel::rectangle_profile(B, B, 0),
                                  tunnel::axis_frame(0, 0, Eigen::Vector3d::Zero(), "axis"),
                                  Eigen::Vector3d::Zero(), sets, o);
  }
  // The triangle's inradius, the apex's depth and the weight A h / 3 with
  // A = 3 sqrt(3) r^2: sqrt(3) r^2 h x 2700 x 9.81 (138 kN).
  double r() const { return B / (2 * std::sqrt(3.0)); }
  double h() const { return r() / std::tan(beta); }
  double weight() const { return std::sqrt(3.0) * r() * r() * h() * 2700 * 9.81; }
  double fos(double W, double T, double P) const {
    return ((W * std::cos(beta) + T * std::sin(beta)) * std::tan(phi) + T * std::cos(beta) + P) /
           (W * std::sin(beta));
  }
};

const tunnel::Wedge& the_face_wedge(const tunnel::WedgeAnalysis& a) {
  const tunnel::Wedge* found = nullptr;
  for (const auto& w : a.wedges)
    if (w.place == tunnel::WedgePlace::face && w.mode &&
        w.mode->type == kinematics::ModeType::Sliding) {
      if (found) throw std::runtime_error("two sliding face wedges");
      found = &w;
    }
  if (!found) throw std::runtime_error("no sliding face wedge");
  return *found;
}

// Both runs of the check, as firmware-app/support runs them.
SupportCheck check_on_face(const FaceWedge& g, const SupportClass& c) {
  const tunnel::WedgeAnalysis pattern = g.analyse(with_class_support({}, c));
  const tunnel::WedgeAnalysis face = g.analyse(with_class_face_support({}, c));
  return check_support(c, &pattern, {}, &face);
}

WedgeSupportCheck face_check(const SupportCheck& s) {
  for (const auto& w : s.wedges)
    if (w.place == "face") return w;
  throw std::runtime_error("no face wedge checked");
}

TEST(SupportCheck, TheFaceWedgeIsTheLargestTriangleAndSlidesOutOfTheFace) {
  const FaceWedge g;
  const tunnel::WedgeAnalysis a = g.analyse({});
  const tunnel::Wedge& w = the_face_wedge(a);
  // The triangle's side 6 m and depth 1 m: the fit's bisection and the
  // chords, ~1e-9 m.
  double side = 0;
  for (int i = 0; i < 3; ++i) side = std::max(side, (w.outline[i] - w.outline[(i + 1) % 3]).norm());
  EXPECT_NEAR(side, g.B, 1e-6);
  EXPECT_NEAR(w.apex_height, g.h(), 1e-6);
  // The solid's weight against A h / 3: the fit's 1e-9 m on 6 m and 1 m.
  EXPECT_NEAR(w.weight, g.weight(), 1e-6 * g.weight());
  ASSERT_TRUE(w.fos);
  EXPECT_NEAR(*w.fos, std::tan(g.phi) / std::tan(g.beta), 1e-9);
}

TEST(SupportCheck, TheClassesFaceBoltsHoldTheFaceWedge) {
  const FaceWedge g;
  SupportClass c = pattern_class(4.0, 1.0, 1e5);  // roof and walls: they do not reach the face
  c.face.bolts = BoltPattern{4.0, 1.0, 5e4, std::nullopt};  // GRP 4 m, 1 m, 50 kN
  const SupportCheck s = check_on_face(g, c);
  const WedgeSupportCheck w = face_check(s);
  EXPECT_EQ(w.mode, "sliding");
  ASSERT_GT(w.bolts, 6);                 // ~15 m² of face at 1 m
  EXPECT_EQ(w.bolts_anchored, w.bolts);  // 4 m reach past the 1 m apex
  EXPECT_TRUE(w.bolts_reach_past_apex);
  ASSERT_TRUE(w.fos_supported);
  // The fit's 1e-9 m in the weight: 1e-6 relative.
  EXPECT_NEAR(*w.fos_supported, g.fos(g.weight(), w.bolts * 5e4, 0), 1e-6 * *w.fos_supported);
  EXPECT_FALSE(w.below_target);
  // The apex 1 m ahead plus 1 m of anchorage.
  EXPECT_NEAR(w.required_bolt_length_m, g.h() + kMinBoltAnchorageM, 1e-6);
  EXPECT_EQ(s.below_target, 0);
}

TEST(SupportCheck, TheFaceWedgeWithoutFaceSupportOrWithShortFaceBoltsIsFlagged) {
  const FaceWedge g;
  // The pattern of the roof and walls alone: the face wedge as it stands.
  const SupportClass none = pattern_class(4.0, 1.0, 1e5);
  const WedgeSupportCheck bare = face_check(check_on_face(g, none));
  ASSERT_TRUE(bare.fos_supported);
  EXPECT_NEAR(*bare.fos_supported, std::tan(g.phi) / std::tan(g.beta), 1e-9);
  EXPECT_EQ(bare.bolts, 0);
  EXPECT_TRUE(bare.below_target);
  ASSERT_EQ(bare.fixes.size(), 1u);
  EXPECT_NE(bare.fixes[0].find("face bolts: the class has none"), std::string::npos)
      << bare.fixes[0];

  // Face bolts of 0.3 m: only those within 0.3 m of the wedge's edges on
  // the face (its depth there below 0.3 m) reach past it. Their capacity
  // would give FoS 2 were they all anchored.
  SupportClass short_bolts = none;
  short_bolts.face.bolts = BoltPattern{0.3, 1.0, 1e3, std::nullopt};
  const int n = face_check(check_on_face(g, short_bolts)).bolts;
  ASSERT_GT(n, 6);
  const double W = g.weight();
  // FoS(T) = 2, linear in T.
  const double t2 = (2 * W * std::sin(g.beta) - W * std::cos(g.beta) * std::tan(g.phi)) /
                    (std::sin(g.beta) * std::tan(g.phi) + std::cos(g.beta));
  short_bolts.face.bolts->capacity_n = t2 / n;
  const WedgeSupportCheck w = face_check(check_on_face(g, short_bolts));
  EXPECT_FALSE(w.bolts_reach_past_apex);
  ASSERT_LT(w.bolts_anchored, 0.7 * n);  // FoS(0.7 T2) < 1.5
  ASSERT_TRUE(w.fos_supported);
  // The fit's 1e-9 m in the weight: 1e-6.
  EXPECT_NEAR(*w.fos_supported, g.fos(W, w.bolts_anchored * t2 / n, 0), 1e-6);
  EXPECT_TRUE(w.below_target);
  ASSERT_FALSE(w.fixes.empty());
  EXPECT_NE(w.fixes[0].find("face bolts of at least 2.00 m"), std::string::npos) << w.fixes[0];
}

TEST(SupportCheck, TheClassesFaceShotcreteResistsTheFaceWedgeOverItsOutline) {
  const FaceWedge g;
  SupportClass c;
  c.name = "SC3";
  c.face.shotcrete_m = 0.01;
  c.shotcrete_shear_pa = 1e5;  // P = 0.01 m x 0.1 MPa x 18 m = 18 kN
  const WedgeSupportCheck w = face_check(check_on_face(g, c));
  const double P = 0.01 * 1e5 * 3 * g.B;
  ASSERT_TRUE(w.fos_supported);
  // The outline from the solid's edges: ~1e-9 relative.
  EXPECT_NEAR(*w.fos_supported, g.fos(g.weight(), 0, P), 1e-6);
  EXPECT_GT(*w.fos_supported, std::tan(g.phi) / std::tan(g.beta));
  EXPECT_TRUE(w.below_target);  // 18 kN against a 138 kN wedge: FoS 0.48
}

}  // namespace
}  // namespace rockface::analysis
