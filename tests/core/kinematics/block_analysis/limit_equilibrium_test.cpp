// Limit equilibrium of whole polyhedral blocks under their effects, against
// closed-form solutions: a block on a plane, a symmetric wedge, and Hoek &
// Bray's plane failure with a tension crack, water and a bolt.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <gtest/gtest.h>

#include "core/blocks/construction.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect_bolt.h"
#include "core/kinematics/effects/effect_force.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/kinematics/effects/effect_seismic.h"
#include "core/kinematics/effects/effect_water.h"

namespace rockface::kinematics {
namespace {

using blocks::HalfSpaceInput;
using blocks::PlaneKind;
using geometry::HalfSpace;

constexpr double kG = 9.81;
constexpr double kRho = 2600;
constexpr double kGammaW = 9810;

Eigen::Vector3d normal_deg(double dip, double dipdir) {
  return geometry::plane_normal_deg(dip, dipdir);
}

// A half-space of a scene plane (dip, dip direction through a point), with
// the block on `side`.
HalfSpaceInput plane(int index, const std::string& name, PlaneKind kind, double dip, double dipdir,
                     const Eigen::Vector3d& point, HalfSpace side) {
  HalfSpaceInput h;
  h.index = index;
  h.name = name;
  h.kind = kind;
  h.plane = geometry::Plane::from_orientation({deg_to_rad(dip), deg_to_rad(dipdir)}, point);
  h.side = side;
  return h;
}

// Same, from the normal pointing into the block.
HalfSpaceInput bounding(int index, const std::string& name, PlaneKind kind,
                        const Eigen::Vector3d& inward, const Eigen::Vector3d& point) {
  const geometry::PlaneOrientation o = geometry::plane_orientation(inward);
  HalfSpaceInput h;
  h.index = index;
  h.name = name;
  h.kind = kind;
  h.plane = geometry::Plane::from_orientation(o, point);
  h.side = h.plane.normal.dot(inward) > 0 ? HalfSpace::Upper : HalfSpace::Lower;
  return h;
}

blocks::Polyhedron bounded(const std::string& id, const std::vector<HalfSpaceInput>& h) {
  auto c = blocks::build_convex_block(id, h);
  EXPECT_EQ(c.outcome, blocks::ConvexOutcome::Bounded);
  return *c.polyhedron;
}

// A slab of length a (down the dip), width b and thickness t resting on a
// joint dipping psi towards dipdir; every other face is free.
blocks::Polyhedron block_on_plane(double psi, double dipdir, double a, double b, double t) {
  const Eigen::Vector3d n = normal_deg(psi, dipdir);
  const Eigen::Vector3d d = geometry::line_direction({deg_to_rad(dipdir), deg_to_rad(psi)});
  const Eigen::Vector3d s = n.cross(d);
  const Eigen::Vector3d o(3, -2, 1);
  return bounded("slab", {plane(0, "J1", PlaneKind::Joint, psi, dipdir, o, HalfSpace::Upper),
                          bounding(1, "top", PlaneKind::FreeFace, -n, o + t * n),
                          bounding(2, "up", PlaneKind::FreeFace, d, o),
                          bounding(3, "down", PlaneKind::FreeFace, -d, o + a * d),
                          bounding(4, "left", PlaneKind::FreeFace, s, o),
                          bounding(5, "right", PlaneKind::FreeFace, -s, o + b * s)});
}

Effects gravity_only() {
  Effects e;
  e.push_back(std::make_unique<GravityEffect>(Eigen::Vector3d(0, 0, -kG)));
  return e;
}

// The polyhedron's plane index of a named plane.
int plane_of(const blocks::Polyhedron& p, const std::string& name) {
  for (int i = 0; i < static_cast<int>(p.planes().size()); ++i)
    if (p.planes()[i].name == name) return i;
  return -1;
}

std::vector<JointStrength> strengths(const blocks::Polyhedron& p, double phi_deg, double c) {
  std::vector<JointStrength> s(p.planes().size());
  for (auto& x : s) x = {deg_to_rad(phi_deg), c};
  return s;
}

// Factors of safety from exact geometry (corners from 3x3 solves, ~1e-15
// relative) and a handful of summed terms: 1e-10 relative is far below any
// engineering meaning and far above the rounding.
constexpr double kClosedForm = 1e-10;

TEST(LimitEquilibrium, BlockOnAPlaneFollowsTanPhiOverTanPsi) {
  const Effects g = gravity_only();
  for (double psi : {15.0, 35.0, 50.0}) {
    const blocks::Polyhedron p = block_on_plane(psi, 210, 4, 3, 1.5);
    BlockAnalysisInput in;
    in.density = kRho;
    in.strengths = strengths(p, 30, 0);
    in.effects = &g;
    const BlockAnalysis r = analyse_block(p, in);
    EXPECT_TRUE(r.finiteness.finite.value);
    EXPECT_TRUE(r.finiteness.removable.value);
    EXPECT_FALSE(r.finiteness.removable.marginal);
    ASSERT_TRUE(r.mode);
    EXPECT_EQ(r.mode->type, ModeType::Sliding);
    ASSERT_EQ(r.mode->planes.size(), 1u);
    EXPECT_EQ(p.planes()[r.mode->planes[0]].name, "J1");
    ASSERT_TRUE(r.fos);
    EXPECT_NEAR(*r.fos, std::tan(deg_to_rad(30)) / std::tan(deg_to_rad(psi)), kClosedForm);
    EXPECT_NEAR(r.mass.volume, 4 * 3 * 1.5, 18 * kClosedForm);
    EXPECT_EQ(r.effects_used, std::vector<std::string>{"gravity"});
  }
}

TEST(LimitEquilibrium, BlockOnAPlaneWithCohesionOverTheContactArea) {
  const double psi = deg_to_rad(40), phi = deg_to_rad(30), c = 25e3;
  const blocks::Polyhedron p = block_on_plane(40, 95, 4, 3, 1.5);
  const Effects g = gravity_only();
  BlockAnalysisInput in;
  in.density = kRho;
  in.strengths = strengths(p, 30, c);
  in.effects = &g;
  const BlockAnalysis r = analyse_block(p, in);
  const double W = kRho * kG * 4 * 3 * 1.5, A = 4 * 3;
  ASSERT_TRUE(r.fos);
  EXPECT_NEAR(*r.fos, (W * std::cos(psi) * std::tan(phi) + c * A) / (W * std::sin(psi)),
              kClosedForm);
}

TEST(LimitEquilibrium, SymmetricWedgeFollowsWedgeFactor) {
  // Joints dipping 60 towards 135 and 225 meet along a line plunging psi_i
  // towards 180, daylighting in a 75-degree face; horizontal crest at 10 m.
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  const blocks::Polyhedron p =
      bounded("wedge", {plane(0, "J1", PlaneKind::Joint, 60, 135, o, HalfSpace::Upper),
                        plane(1, "J2", PlaneKind::Joint, 60, 225, o, HalfSpace::Upper),
                        plane(2, "F", PlaneKind::FreeFace, 75, 180, o, HalfSpace::Lower),
                        plane(3, "T", PlaneKind::FreeFace, 0, 0, {0, 0, 10}, HalfSpace::Lower)});
  const Effects g = gravity_only();
  BlockAnalysisInput in;
  in.density = kRho;
  in.strengths = strengths(p, 30, 0);
  in.effects = &g;
  const BlockAnalysis r = analyse_block(p, in);
  ASSERT_TRUE(r.finiteness.removable.value);
  ASSERT_TRUE(r.mode);
  ASSERT_EQ(r.mode->planes.size(), 2u);
  // Hoek & Bray: FoS = K tan(phi) / tan(psi_i), wedge factor K = sin(beta) /
  // sin(xi / 2), beta = 90 degrees for a symmetric wedge, xi the angle
  // between the faces (pi minus the angle between their normals).
  const Eigen::Vector3d n1 = normal_deg(60, 135), n2 = normal_deg(60, 225);
  const double psi_i = std::asin(std::abs(n1.cross(n2).normalized().z()));
  const double xi = std::numbers::pi - std::acos(n1.dot(n2));
  const double expected = std::tan(deg_to_rad(30)) / std::tan(psi_i) / std::sin(xi / 2);
  ASSERT_TRUE(r.fos);
  EXPECT_NEAR(*r.fos, expected, kClosedForm);
  EXPECT_NEAR(r.mode->normal_forces[0], r.mode->normal_forces[1], r.mass.mass * kG * kClosedForm);
}

// Hoek & Bray, Rock Slope Engineering (plane failure, tension crack in the
// upper slope surface): slope height H, face angle psi_f, sliding plane
// psi_p daylighting at the toe, a vertical crack of depth z, water standing
// zw deep in the crack and draining along the sliding plane to the toe, a
// bolt of tension T at theta to the normal of the sliding plane. Per metre
// of slope:
//   A = (H - z) / sin(psi_p)
//   W = 1/2 gamma_r H^2 [(1 - (z/H)^2) cot(psi_p) - cot(psi_f)]
//   U = 1/2 gamma_w zw (H - z) cosec(psi_p)     (uplift on the plane)
//   V = 1/2 gamma_w zw^2                         (thrust in the crack)
//   FoS = (c A + (W cos psi_p - U - V sin psi_p + T cos theta) tan phi)
//         / (W sin psi_p + V cos psi_p - T sin theta)
// The polyhedron: the sliding block between the plane, the crack (both
// joints, carrying water), the face and the upper surface (free), cut to a
// width w by two vertical free faces. The water is the `water` effect with a
// phreatic plane through the toe and the water level in the crack: its
// integrated pressures must reproduce U and V.
struct PlaneFailure {
  double H = 20, psi_f = 60, psi_p = 30, z = 6, zw = 4, w = 5;
  double phi = 35, c = 10e3, T = 50e3, theta = 40;  // T per metre of slope

  // South-facing slope (dip direction 180): out of the slope is -y.
  double crack_y() const { return (H - z) / std::tan(deg_to_rad(psi_p)); }
  blocks::Polyhedron block() const {
    const Eigen::Vector3d toe(0, 0, 0), crack_top(0, crack_y(), H);
    return bounded("plane-failure",
                   {plane(0, "P", PlaneKind::Joint, psi_p, 180, toe, HalfSpace::Upper),
                    plane(1, "C", PlaneKind::Joint, 90, 180, crack_top, HalfSpace::Upper),
                    plane(2, "F", PlaneKind::FreeFace, psi_f, 180, toe, HalfSpace::Lower),
                    plane(3, "U", PlaneKind::FreeFace, 0, 0, crack_top, HalfSpace::Lower),
                    plane(4, "L0", PlaneKind::FreeFace, 90, 90, toe, HalfSpace::Upper),
                    plane(5, "L1", PlaneKind::FreeFace, 90, 90, {w, 0, 0}, HalfSpace::Lower)});
  }
  std::unique_ptr<WaterEffect> water() const {
    // Through the toe and the water level in the crack, level along strike.
    const Eigen::Vector3d level(0, crack_y(), H - z + zw);
    const Eigen::Vector3d normal = Eigen::Vector3d::UnitX().cross(level).normalized();
    return std::make_unique<WaterEffect>(kGammaW, Eigen::Vector3d::Zero(),
                                         normal.z() > 0 ? normal : Eigen::Vector3d(-normal),
                                         std::vector<int>{0, 1});
  }
  std::unique_ptr<BoltEffect> bolt() const {
    // Into the slope (trend 0) plunging 90 - (psi_p + theta): theta from the
    // normal of the sliding plane, tilted up the dip.
    const double plunge = 90 - (psi_p + theta);
    const Eigen::Vector3d dir = geometry::line_direction({deg_to_rad(0), deg_to_rad(plunge)});
    const Eigen::Vector3d head(w / 2, 0.5 * H / std::tan(deg_to_rad(psi_f)), H / 2);  // on the face
    return std::make_unique<BoltEffect>("bolts[0]", head, dir, T * w);
  }

  double W() const {
    const double cp = 1 / std::tan(deg_to_rad(psi_p)), cf = 1 / std::tan(deg_to_rad(psi_f));
    return 0.5 * kRho * kG * H * H * ((1 - (z / H) * (z / H)) * cp - cf);
  }
  double A() const { return (H - z) / std::sin(deg_to_rad(psi_p)); }
  double U() const { return 0.5 * kGammaW * zw * (H - z) / std::sin(deg_to_rad(psi_p)); }
  double V() const { return 0.5 * kGammaW * zw * zw; }
  double fos(bool with_water, bool with_bolt) const {
    const double u = with_water ? U() : 0, v = with_water ? V() : 0, t = with_bolt ? T : 0;
    const double sp = std::sin(deg_to_rad(psi_p)), cp = std::cos(deg_to_rad(psi_p));
    const double st = std::sin(deg_to_rad(theta)), ct = std::cos(deg_to_rad(theta));
    return (c * A() + (W() * cp - u - v * sp + t * ct) * std::tan(deg_to_rad(phi))) /
           (W() * sp + v * cp - t * st);
  }
};

TEST(LimitEquilibrium, PlaneFailureWeightAndWaterForcesMatchHoekAndBray) {
  const PlaneFailure pf;
  const blocks::Polyhedron p = pf.block();
  const blocks::MassProperties mp = blocks::mass_properties(p, kRho);
  EXPECT_NEAR(mp.mass * kG, pf.W() * pf.w, pf.W() * pf.w * kClosedForm);
  EXPECT_NEAR(mp.plane_areas[plane_of(p, "P")], pf.A() * pf.w, pf.A() * pf.w * kClosedForm);
  const EffectLoad water = pf.water()->load(p, mp);
  ASSERT_TRUE(water.acts);
  ASSERT_EQ(water.faces.size(), 2u);
  for (const FaceLoad& fl : water.faces) {
    const std::string& name = p.planes()[fl.plane].name;
    if (name == "P") {
      EXPECT_NEAR(fl.normal, pf.U() * pf.w, pf.U() * pf.w * kClosedForm);
    }
    if (name == "C") {
      EXPECT_NEAR(fl.normal, pf.V() * pf.w, pf.V() * pf.w * kClosedForm);
      // Triangular pressure: the thrust acts a third of zw above the crack bottom.
      EXPECT_NEAR(fl.point.z(), pf.H - pf.z + pf.zw / 3, 1e-9);
    }
  }
}

TEST(LimitEquilibrium, PlaneFailureWithCrackWaterAndBoltMatchesHoekAndBray) {
  const PlaneFailure pf;
  const blocks::Polyhedron p = pf.block();
  for (const bool with_water : {false, true})
    for (const bool with_bolt : {false, true}) {
      Effects e;
      e.push_back(std::make_unique<GravityEffect>(Eigen::Vector3d(0, 0, -kG)));
      if (with_water) e.push_back(pf.water());
      if (with_bolt) e.push_back(pf.bolt());
      BlockAnalysisInput in;
      in.density = kRho;
      in.strengths.resize(p.planes().size());
      in.strengths[plane_of(p, "P")] = {deg_to_rad(pf.phi), pf.c};
      in.strengths[plane_of(p, "C")] = {deg_to_rad(pf.phi), 0};
      in.effects = &e;
      const BlockAnalysis r = analyse_block(p, in);
      EXPECT_TRUE(r.finiteness.removable.value);
      ASSERT_TRUE(r.mode);
      EXPECT_EQ(r.mode->type, ModeType::Sliding);
      ASSERT_EQ(r.mode->planes.size(), 1u);
      EXPECT_EQ(p.planes()[r.mode->planes[0]].name, "P");
      ASSERT_TRUE(r.fos);
      EXPECT_NEAR(*r.fos, pf.fos(with_water, with_bolt), kClosedForm)
          << "water " << with_water << " bolt " << with_bolt;
      EXPECT_TRUE(r.opened_planes.empty());
      EXPECT_EQ(r.effects_used.size(), 1u + with_water + with_bolt);
    }
  // The case with everything is a real slope: marginally stable.
  EXPECT_GT(pf.fos(true, true), 1.0);
  EXPECT_LT(pf.fos(true, false), pf.fos(false, false));
}

TEST(LimitEquilibrium, WaterThatLiftsTheBlockOpensTheJoint) {
  // Water standing 10 m above a 1.5 m slab on a 20-degree joint: the uplift
  // exceeds W cos(psi), the joint opens and neither its friction nor its
  // cohesion holds the block. A formula that kept them would give
  // (c A + (W cos psi - U) tan phi) / (W sin psi) > 0 here.
  const blocks::Polyhedron p = block_on_plane(20, 0, 4, 3, 1.5);
  Effects e;
  e.push_back(std::make_unique<GravityEffect>(Eigen::Vector3d(0, 0, -kG)));
  e.push_back(
      std::make_unique<WaterEffect>(kGammaW, Eigen::Vector3d(0, 0, 20), Eigen::Vector3d::UnitZ()));
  BlockAnalysisInput in;
  in.density = kRho;
  in.strengths = strengths(p, 35, 200e3);
  in.effects = &e;
  const BlockAnalysis r = analyse_block(p, in);
  const blocks::MassProperties& mp = r.mass;
  const double W = mp.mass * kG, psi = deg_to_rad(20);
  const int base = plane_of(p, "J1");
  // Uplift: fully submerged, so the integral is the head at the face
  // centroid times the area.
  const double U = kGammaW * (20 - blocks::face_centroid(p, p.faces_on_plane(base)[0]).z()) *
                   mp.plane_areas[base];
  ASSERT_GT(U, W * std::cos(psi));
  const double naive =
      (200e3 * mp.plane_areas[base] + (W * std::cos(psi) - U) * std::tan(deg_to_rad(35))) /
      (W * std::sin(psi));
  ASSERT_GT(naive, 0.5);
  ASSERT_TRUE(r.mode);
  EXPECT_EQ(r.mode->type, ModeType::Lifting);
  ASSERT_TRUE(r.fos);
  EXPECT_EQ(*r.fos, 0.0);
  ASSERT_EQ(r.opened_planes.size(), 1u);
  EXPECT_EQ(r.opened_planes[0], base);
  EXPECT_NE(std::find(r.notes.begin(), r.notes.end(),
                      "face J1 opens under water pressure: its friction and cohesion do not count"),
            r.notes.end());
}

TEST(LimitEquilibrium, WaterOnOneWedgeFaceOpensItAndTheWedgeSlidesOnTheOther) {
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  const blocks::Polyhedron p =
      bounded("wedge", {plane(0, "J1", PlaneKind::Joint, 60, 135, o, HalfSpace::Upper),
                        plane(1, "J2", PlaneKind::Joint, 60, 225, o, HalfSpace::Upper),
                        plane(2, "F", PlaneKind::FreeFace, 75, 180, o, HalfSpace::Lower),
                        plane(3, "T", PlaneKind::FreeFace, 0, 0, {0, 0, 10}, HalfSpace::Lower)});
  // Water only on J1. Resolving on the two planes, uplift U1 on J1 takes
  // U1 off J1's normal force N1 = W cos(psi_i) / (2 sin(xi / 2)) ~ 0.4 W and
  // leaves J2's unchanged, so U1 = W opens J1, while the block still presses
  // on J2 alone (-R . n2 = W / 2 - U1 n1 . n2 = W / 4 > 0). The phreatic
  // level giving U1 = W with J1 fully submerged (a linear pressure over a
  // triangle integrates to its value at the centroid times the area):
  const int j1 = plane_of(p, "J1"), j2 = plane_of(p, "J2");
  const auto& f1 = p.faces()[p.faces_on_plane(j1)[0]];
  ASSERT_EQ(f1.loop.size(), 3u);
  const Eigen::Vector3d a = p.vertices()[f1.loop[0]], b = p.vertices()[f1.loop[1]],
                        cc = p.vertices()[f1.loop[2]];
  const double area1 = 0.5 * (b - a).cross(cc - a).norm();
  const double W = blocks::mass_properties(p, kRho).mass * kG;
  const double level = (a + b + cc).z() / 3 + W / (kGammaW * area1);
  ASSERT_GT(level, std::max({a.z(), b.z(), cc.z()}));  // fully submerged
  Effects e;
  e.push_back(std::make_unique<GravityEffect>(Eigen::Vector3d(0, 0, -kG)));
  e.push_back(std::make_unique<WaterEffect>(kGammaW, Eigen::Vector3d(0, 0, level),
                                            Eigen::Vector3d::UnitZ(), std::vector<int>{0}));
  const double c = 5e3, phi = deg_to_rad(30);
  BlockAnalysisInput in;
  in.density = kRho;
  in.strengths = strengths(p, 30, c);
  in.effects = &e;
  const BlockAnalysis r = analyse_block(p, in);
  const double U1 = W;
  const Eigen::Vector3d R = Eigen::Vector3d(0, 0, -r.mass.mass * kG) + U1 * normal_deg(60, 135);
  const Eigen::Vector3d n2 = normal_deg(60, 225);
  const double N2 = -R.dot(n2), S = (R - R.dot(n2) * n2).norm();
  ASSERT_GT(N2, 0);
  ASSERT_TRUE(r.mode);
  EXPECT_EQ(r.mode->type, ModeType::Sliding);
  ASSERT_EQ(r.mode->planes.size(), 1u);
  EXPECT_EQ(r.mode->planes[0], j2);
  ASSERT_TRUE(r.fos);
  EXPECT_NEAR(*r.fos, (N2 * std::tan(phi) + c * r.mass.plane_areas[j2]) / S, kClosedForm);
  EXPECT_EQ(r.opened_planes, std::vector<int>{j1});
}

TEST(LimitEquilibrium, PseudoStaticSeismicLoadFollowsClosedForm) {
  // Horizontal acceleration k g towards the dip direction (out of the
  // slope): FoS = (cos psi - k sin psi) tan phi / (sin psi + k cos psi).
  const double psi = deg_to_rad(25), phi = deg_to_rad(35), k = 0.15;
  const blocks::Polyhedron p = block_on_plane(25, 90, 4, 3, 1.5);
  Effects e;
  e.push_back(std::make_unique<GravityEffect>(Eigen::Vector3d(0, 0, -kG)));
  e.push_back(std::make_unique<SeismicEffect>(Eigen::Vector3d(k * kG, 0, 0)));  // east = dipdir 90
  BlockAnalysisInput in;
  in.density = kRho;
  in.strengths = strengths(p, 35, 0);
  in.effects = &e;
  const BlockAnalysis r = analyse_block(p, in);
  EXPECT_EQ(r.effects_used, (std::vector<std::string>{"gravity", "seismic"}));
  ASSERT_TRUE(r.fos);
  EXPECT_NEAR(
      *r.fos,
      (std::cos(psi) - k * std::sin(psi)) * std::tan(phi) / (std::sin(psi) + k * std::cos(psi)),
      kClosedForm);
}

TEST(LimitEquilibrium, AppliedForceActsAtItsPointWithItsMoment) {
  // A force pulling the slab up the dip, applied at a corner of its top:
  // it enters the resultant and gives the moment r x F about the centroid.
  const double psi = deg_to_rad(30), phi = deg_to_rad(30), F = 2e5;
  const blocks::Polyhedron p = block_on_plane(30, 0, 4, 3, 1.5);
  const Eigen::Vector3d up_dip = -geometry::line_direction({0, psi});
  int corner = 0;  // the highest vertex, on the block's surface
  for (int v = 0; v < static_cast<int>(p.vertices().size()); ++v)
    if (p.vertices()[v].z() > p.vertices()[corner].z()) corner = v;
  for (const ForceFrame frame : {ForceFrame::Space, ForceFrame::Block}) {
    Effects e;
    e.push_back(std::make_unique<GravityEffect>(Eigen::Vector3d(0, 0, -kG)));
    e.push_back(
        std::make_unique<ForceEffect>("forces[0]", F * up_dip, p.absolute_vertex(corner), frame));
    BlockAnalysisInput in;
    in.density = kRho;
    in.strengths = strengths(p, 30, 0);
    in.effects = &e;
    const BlockAnalysis r = analyse_block(p, in);
    const double W = r.mass.mass * kG;
    EXPECT_LE((r.force - (Eigen::Vector3d(0, 0, -W) + F * up_dip)).norm(), W * kClosedForm);
    const Eigen::Vector3d arm = p.vertices()[corner] - r.mass.centroid;
    EXPECT_LE((r.moment - arm.cross(F * up_dip)).norm(), F * arm.norm() * kClosedForm);
    ASSERT_TRUE(r.fos);
    EXPECT_NEAR(*r.fos, W * std::cos(psi) * std::tan(phi) / (W * std::sin(psi) - F), kClosedForm);
  }
}

TEST(LimitEquilibrium, BoltOutsideTheBlockDoesNotActAndSaysSo) {
  const blocks::Polyhedron p = block_on_plane(30, 0, 4, 3, 1.5);
  Effects e;
  e.push_back(std::make_unique<GravityEffect>(Eigen::Vector3d(0, 0, -kG)));
  e.push_back(std::make_unique<BoltEffect>("bolts[0]", Eigen::Vector3d(100, 100, 100),
                                           Eigen::Vector3d(0, 1, 0), 1e6));
  BlockAnalysisInput in;
  in.density = kRho;
  in.strengths = strengths(p, 30, 0);
  in.effects = &e;
  const BlockAnalysis r = analyse_block(p, in);
  EXPECT_EQ(r.effects_used, std::vector<std::string>{"gravity"});
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("bolts[0] does not act on block slab"), std::string::npos);
  ASSERT_TRUE(r.fos);
  EXPECT_NEAR(*r.fos, std::tan(deg_to_rad(30)) / std::tan(deg_to_rad(30)), kClosedForm);
}

TEST(LimitEquilibrium, NoFrictionMeansNoFactorOfSafety) {
  const blocks::Polyhedron p = block_on_plane(30, 0, 4, 3, 1.5);
  const Effects g = gravity_only();
  BlockAnalysisInput in;
  in.density = kRho;
  in.effects = &g;
  const BlockAnalysis r = analyse_block(p, in);
  ASSERT_TRUE(r.mode);
  EXPECT_EQ(r.mode->type, ModeType::Sliding);
  EXPECT_FALSE(r.fos);
}

}  // namespace
}  // namespace rockface::kinematics
