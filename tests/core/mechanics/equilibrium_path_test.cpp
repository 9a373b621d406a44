// The equilibrium path of single blocks: rigid-plastic joints reproduce
// limit equilibrium (plane failure, wedge), a block under a couple reaches
// its limit point turning where limit equilibrium says it slides, a tall
// column topples under its own weight, rigid motions of the scene and
// survey coordinates change nothing, paths without a limit point stop and
// say so, bad input is named, and a 1e12 Pa/m joint is solved.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/blocks/mass_properties.h"
#include "core/common/error.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect_water.h"
#include "core/mechanics/contact_points.h"
#include "core/mechanics/equilibrium_path.h"
#include "core/mechanics/peak_strength.h"
#include "tests/support/mechanics_blocks.h"

namespace rockface::mechanics {
namespace {

using namespace testing;

constexpr double kRho = 2600;

// Limit-equilibrium FoS of the same block with friction phi on its joints.
double le_fos(const blocks::Polyhedron& p, const kinematics::Effects& e, double phi_deg,
              double cohesion = 0, kinematics::ModeType* mode = nullptr) {
  kinematics::BlockAnalysisInput in;
  in.density = kRho;
  in.effects = &e;
  in.strengths.assign(p.planes().size(), {deg_to_rad(phi_deg), cohesion});
  const kinematics::BlockAnalysis a = kinematics::analyse_block(p, in);
  if (mode && a.mode) *mode = a.mode->type;
  return a.fos.value_or(-1);
}

EquilibriumPath run(const blocks::Polyhedron& p, const kinematics::Effects& e,
                    const JointLawParameters& law, MechanicsOptions o = {},
                    const std::optional<Eigen::Matrix3d>& insitu = std::nullopt) {
  const blocks::MassProperties m = blocks::mass_properties(p, kRho);
  return equilibrium_path(p, m, e, laws(p, law), insitu, o);
}

// The continuation approaches the limit point by halving its step down to
// step / 64 = 7.8e-4 in lambda (the path is vertical, all in lambda, until
// the first contact slips): the FoS is found to within that, from below.
constexpr double kLimitStep = 0.05 / 64;

TEST(EquilibriumPath, RigidPlasticSlabReproducesPlaneFailure) {
  for (double psi : {25.0, 35.0, 50.0}) {
    Slab slab;
    slab.psi = psi;
    const blocks::Polyhedron p = slab.block();
    const kinematics::Effects g = gravity();
    kinematics::ModeType le_mode = kinematics::ModeType::None;
    const double le = le_fos(p, g, 40, 0, &le_mode);
    ASSERT_EQ(le_mode, kinematics::ModeType::Sliding);
    const EquilibriumPath r = run(p, g, coulomb(40));
    ASSERT_EQ(r.outcome, PathOutcome::LimitPoint) << psi;
    ASSERT_TRUE(r.fos_limit_point);
    EXPECT_NEAR(*r.fos_limit_point, le, 2 * kLimitStep) << "psi " << psi;
    EXPECT_FALSE(r.static_mode.rotates);
    // It slides down the dip: the centroid moves along d.
    EXPECT_GT(r.static_mode.translation.normalized().dot(slab.d()), 0.999);
    EXPECT_EQ(r.stability, StabilityKind::Divergence);
    EXPECT_EQ(r.effects_used, std::vector<std::string>{"gravity"});
  }
}

TEST(EquilibriumPath, RigidPlasticSlabWithCohesion) {
  Slab slab;
  const blocks::Polyhedron p = slab.block();
  const kinematics::Effects g = gravity();
  const double le = le_fos(p, g, 30, 20e3);
  const EquilibriumPath r = run(p, g, coulomb(30, 20e3));
  ASSERT_TRUE(r.fos_limit_point);
  EXPECT_NEAR(*r.fos_limit_point, le, 2 * kLimitStep);
}

TEST(EquilibriumPath, RigidPlasticWedgeReproducesWedgeFactor) {
  const blocks::Polyhedron p = wedge();
  const kinematics::Effects g = gravity();
  kinematics::ModeType le_mode = kinematics::ModeType::None;
  const double le = le_fos(p, g, 30, 0, &le_mode);
  ASSERT_EQ(le_mode, kinematics::ModeType::Sliding);
  const EquilibriumPath r = run(p, g, coulomb(30));
  ASSERT_EQ(r.outcome, PathOutcome::LimitPoint);
  ASSERT_TRUE(r.fos_limit_point);
  EXPECT_NEAR(*r.fos_limit_point, le, 2 * kLimitStep);
  EXPECT_FALSE(r.static_mode.rotates);
  // Along the intersection of the joints, plunging south.
  const Eigen::Vector3d line = normal_deg(60, 135).cross(normal_deg(60, 225)).normalized();
  EXPECT_GT(std::abs(r.static_mode.translation.normalized().dot(line)), 0.999);
}

}  // namespace
}  // namespace rockface::mechanics

namespace rockface::mechanics {
namespace {

using namespace testing;

kinematics::Effects with_couple(const Slab& slab, double force) {
  kinematics::Effects e = gravity();
  // Two opposite forces down the dip at either side of the slab: no
  // resultant (limit equilibrium does not see them), a couple about the
  // joint's normal.
  e.push_back(std::make_unique<kinematics::ForceEffect>(
      "forces[0]", force * slab.d(), slab.at(0.5, 0.95, 0.5), kinematics::ForceFrame::Space));
  e.push_back(std::make_unique<kinematics::ForceEffect>(
      "forces[1]", -force * slab.d(), slab.at(0.5, 0.05, 0.5), kinematics::ForceFrame::Space));
  return e;
}

TEST(EquilibriumPath, SlabUnderACoupleTurnsWhereLimitEquilibriumSlides) {
  Slab slab;
  slab.psi = 20;
  slab.a = 4;
  slab.b = 4;
  slab.t = 0.5;
  const blocks::Polyhedron p = slab.block();
  const double weight = kRho * 9.81 * slab.a * slab.b * slab.t;
  const kinematics::Effects e = with_couple(slab, weight * std::sin(deg_to_rad(20)));
  kinematics::ModeType le_mode = kinematics::ModeType::None;
  const double le = le_fos(p, e, 35, 0, &le_mode);
  EXPECT_EQ(le_mode, kinematics::ModeType::Sliding);
  EXPECT_NEAR(le, std::tan(deg_to_rad(35)) / std::tan(deg_to_rad(20)), 1e-9);
  const EquilibriumPath r = run(p, e, coulomb(35));
  ASSERT_EQ(r.outcome, PathOutcome::LimitPoint);
  ASSERT_TRUE(r.fos_limit_point);
  // The couple takes friction the downhill pull cannot have: the block
  // gives way sooner, turning about a point on its base.
  EXPECT_LT(*r.fos_limit_point, 0.8 * le);
  EXPECT_TRUE(r.static_mode.rotates);
  EXPECT_TRUE(r.dynamic_mode.rotates);
  // It turns about the joint's normal (in its own plane).
  EXPECT_GT(std::abs(r.static_mode.rotation.normalized().dot(slab.n())), 0.95);
  EXPECT_EQ(r.effects_used, (std::vector<std::string>{"gravity", "forces"}));
}

TEST(EquilibriumPath, TallColumnTopplesWhereLimitEquilibriumSlides) {
  // 1 m x 1 m base, 4 m tall, on a 30-degree joint with 40 degrees of
  // friction: limit equilibrium says sliding at FoS 1.45, but its weight
  // acts outside its base (tan 30 > 1 / 4): no strength holds it.
  Slab column;
  column.psi = 30;
  column.a = 1;
  column.b = 1;
  column.t = 4;
  const blocks::Polyhedron p = column.block();
  const kinematics::Effects g = gravity();
  kinematics::ModeType le_mode = kinematics::ModeType::None;
  const double le = le_fos(p, g, 40, 0, &le_mode);
  EXPECT_EQ(le_mode, kinematics::ModeType::Sliding);
  EXPECT_GT(le, 1.4);
  const EquilibriumPath r = run(p, g, coulomb(40));
  EXPECT_EQ(r.outcome, PathOutcome::FailsUnderLoads);
  EXPECT_FALSE(r.fos_limit_point);
  EXPECT_TRUE(r.static_mode.rotates);
  // It turns about the downhill edge of its base: about the strike.
  EXPECT_GT(std::abs(r.static_mode.rotation.normalized().dot(column.s())), 0.9);
  EXPECT_EQ(r.stability, StabilityKind::Divergence);
}

// A rigid motion of the whole scene and survey coordinates.
std::vector<Placement> placements() {
  Placement turned;
  turned.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  turned.shift = Eigen::Vector3d(120, -45, 30);
  Placement survey;
  survey.shift = Eigen::Vector3d(512340.0, 5211870.0, 410.0);
  survey.datum = Eigen::Vector3d(512338.0, 5211871.0, 409.0);
  Placement both = turned;
  both.shift += survey.shift;
  both.datum = survey.datum;
  return {turned, survey, both};
}

TEST(EquilibriumPath, RigidMotionAndSurveyCoordinatesChangeNothing) {
  Slab slab;
  slab.psi = 20;
  slab.a = 4;
  slab.b = 4;
  slab.t = 0.5;
  const double weight = kRho * 9.81 * slab.a * slab.b * slab.t;
  const double f = weight * std::sin(deg_to_rad(20));
  const EquilibriumPath ref = run(slab.block(), with_couple(slab, f), coulomb(35));
  ASSERT_TRUE(ref.fos_limit_point);
  for (const Placement& at : placements()) {
    Slab moved = slab;
    kinematics::Effects e;
    e.push_back(std::make_unique<kinematics::GravityEffect>(at.vector({0, 0, -9.81})));
    e.push_back(std::make_unique<kinematics::ForceEffect>("forces[0]", at.vector(f * slab.d()),
                                                          at.point(slab.at(0.5, 0.95, 0.5)),
                                                          kinematics::ForceFrame::Space));
    e.push_back(std::make_unique<kinematics::ForceEffect>("forces[1]", at.vector(-f * slab.d()),
                                                          at.point(slab.at(0.5, 0.05, 0.5)),
                                                          kinematics::ForceFrame::Space));
    const EquilibriumPath r = run(moved.block(at), e, coulomb(35));
    ASSERT_TRUE(r.fos_limit_point);
    // The same path up to the rounding of the moved coordinates and the
    // differences taken along other axes (1e-12 relative); the halving
    // towards the limit can end one minimum step apart.
    EXPECT_NEAR(*r.fos_limit_point, *ref.fos_limit_point, kLimitStep);
    EXPECT_EQ(r.static_mode.rotates, ref.static_mode.rotates);
    // The mode turns with the scene (same sign convention up to the pair).
    const Eigen::Vector3d w = at.rotation * ref.static_mode.rotation;
    EXPECT_GT(std::abs(r.static_mode.rotation.normalized().dot(w.normalized())), 0.99);
  }
}

TEST(EquilibriumPath, BlockPressedIntoTheRockHasNoLimitPoint) {
  Slab flat;
  flat.psi = 0;
  const blocks::Polyhedron p = flat.block();
  const kinematics::Effects g = gravity();
  MechanicsOptions o;
  const EquilibriumPath r = run(p, g, coulomb(30), o);
  EXPECT_EQ(r.outcome, PathOutcome::NoLimitPoint);
  EXPECT_FALSE(r.fos_limit_point);
  EXPECT_LT(r.steps, o.max_steps);
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes.back().find("no limit point"), std::string::npos);
  EXPECT_EQ(r.stability, StabilityKind::Stable);
}

TEST(EquilibriumPath, StepBudgetEndsThePathAndSaysSo) {
  Slab slab;
  MechanicsOptions o;
  o.max_steps = 3;
  const EquilibriumPath r = run(slab.block(), gravity(), coulomb(40), o);
  EXPECT_EQ(r.outcome, PathOutcome::StepBudget);
  EXPECT_FALSE(r.fos_limit_point);
  EXPECT_LE(r.steps, 3);
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes.back().find("3 steps"), std::string::npos);
}

TEST(EquilibriumPath, BadInputIsNamed) {
  auto where = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const InputError& e) {
      return e.where();
    }
    return "no error";
  };
  JointLawParameters negative = coulomb(30);
  negative.normal_stiffness = -1e9;
  EXPECT_EQ(where([&] { make_joint_law(negative); }), "joint_law.normal_stiffness");
  EXPECT_EQ(where([&] { make_joint_law(barton(25, 1e10)); }), "joint_law.jrc");
  EXPECT_EQ(where([&] { make_joint_law(barton(-1, 1e10)); }), "joint_law.jrc");
  Slab slab;
  const blocks::Polyhedron p = slab.block();
  MechanicsOptions dense;
  dense.contact_density = 0;
  EXPECT_EQ(where([&] { run(p, gravity(), coulomb(30), dense); }), "analysis.contact_density");
  MechanicsOptions step;
  step.step = -0.1;
  EXPECT_EQ(where([&] { run(p, gravity(), coulomb(30), step); }), "analysis.continuation_step");
  // A joint face without a law.
  const blocks::MassProperties m = blocks::mass_properties(p, kRho);
  EXPECT_EQ(where([&] {
              equilibrium_path(p, m, gravity(), std::vector<std::shared_ptr<const JointLaw>>(),
                               std::nullopt, {});
            }),
            "joints.J1");
}

TEST(EquilibriumPath, StiffRoughJointIsSolved) {
  // Barton-Bandis (JRC 10, JCS 100 MPa, phi_b 30) at 1e12 Pa/m: stage B's
  // ~1 mm of slip against dilation into a joint whose elastic range is
  // 1e-8 m. With the laws' consistent tangents the path reaches its limit
  // point well inside the default budget (~75 of 400 steps).
  Slab slab;
  const blocks::Polyhedron p = slab.block();
  const MechanicsOptions o;
  const EquilibriumPath stiff = run(p, gravity(), barton(10, 1e12), o);
  ASSERT_EQ(stiff.outcome, PathOutcome::LimitPoint);
  ASSERT_TRUE(stiff.fos_limit_point);
  EXPECT_LT(stiff.steps, o.max_steps / 2);
  for (const PathPoint& pt : stiff.path) {
    EXPECT_TRUE(std::isfinite(pt.displacement));
    EXPECT_TRUE(pt.translation.allFinite() && pt.rotation.allFinite());
  }
  // The rigid-plastic value with the same peak: Coulomb at Barton's peak
  // friction angle at the limit point's mean normal stress, which is the
  // weight's normal part over the base (W cos psi / A = rho g t cos psi).
  const double sigma = kRho * 9.81 * slab.t * std::cos(deg_to_rad(slab.psi));
  const double phi_peak = BartonBandisPeak(barton(10, 1e12)).peak_angle(sigma);
  // It slides down the dip, rising off the joint at the peak's dilation
  // angle d_p = (phi_peak - phi_r) / M; equilibrium is lost by divergence
  // (the critical eigenvalue is real at the limit). d_p varies over the
  // base with the normal stress (16.5 to 20 degrees for 10 to 52 kPa):
  // the mode's rise is its mean to within 1.5 degrees.
  EXPECT_FALSE(stiff.static_mode.rotates);
  const Eigen::Vector3d mode = stiff.static_mode.translation.normalized();
  EXPECT_GT(mode.dot(slab.d()), 0.9);
  const double rise = std::atan2(mode.dot(slab.n()), mode.dot(slab.d()));
  EXPECT_NEAR(rad_to_deg(rise), rad_to_deg(phi_peak - deg_to_rad(30)) / 2, 1.5);
  EXPECT_EQ(stiff.stability, StabilityKind::Divergence);
  // Before the limit, while some contacts slip and others stick, the
  // consistent tangent is not symmetric (friction kn tan(phi) one way,
  // dilation kn tan(d) the other) and has complex pairs: they are noted
  // with their cause, and they end before the limit.
  ASSERT_TRUE(stiff.flutter_lambda);
  EXPECT_LT(*stiff.flutter_lambda, *stiff.fos_limit_point);
  bool explained = false;
  for (const std::string& n : stiff.notes)
    explained = explained || n.find("not symmetric") != std::string::npos;
  EXPECT_TRUE(explained);
  const double rigid = le_fos(p, gravity(), rad_to_deg(phi_peak));
  ASSERT_NEAR(rigid, std::tan(phi_peak) / std::tan(deg_to_rad(slab.psi)), 1e-9);
  // Expected: below the rigid-plastic value by Jensen's gap. The normal
  // stress is not uniform on the base (the shear at the base and the
  // weight at the centroid make a moment: ~10 to ~52 kPa across it at
  // density 3) and Barton's peak strength sigma tan(phi_r + JRC log10(JCS
  // / sigma)) is concave in sigma (capped at 70 degrees below 10 kPa), so
  // the contacts together carry less than the peak at the mean stress:
  // 1.5 % here (1.8 % at density 2). The limit point itself is found to ~0.1 % (halving onto
  // it; the increments of the dilation integrated at each step's end
  // stress). So the FoS lies 0 to 3 % below the rigid-plastic value.
  EXPECT_LT(*stiff.fos_limit_point, rigid);
  EXPECT_GT(*stiff.fos_limit_point, 0.97 * rigid);
  // The same joint at 1e10 Pa/m: the peak does not depend on the
  // stiffness (only the elastic part tau / ks of the peak displacement
  // does, 1e-4 of it at 1e10), and the steps are capped at 2 % of the peak
  // displacement so that each path is within ~0.05 % of its converged
  // limit point: they agree to 0.2 %.
  const EquilibriumPath soft = run(p, gravity(), barton(10, 1e10), o);
  ASSERT_TRUE(soft.fos_limit_point);
  EXPECT_NEAR(*stiff.fos_limit_point, *soft.fos_limit_point, 2e-3 * *soft.fos_limit_point);
}

TEST(EquilibriumPath, WaterUpliftAsFollowerLoadMatchesLimitEquilibrium) {
  // A phreatic surface 1 m above the slab's base centre: uplift on the
  // joint face, carried as a follower load (it turns with the face).
  Slab slab;
  const blocks::Polyhedron p = slab.block();
  kinematics::Effects e = gravity();
  e.push_back(std::make_unique<kinematics::WaterEffect>(
      9810, slab.at(0.5, 0.5, 0) + Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ()));
  const double le = le_fos(p, e, 40);
  const double dry = le_fos(p, gravity(), 40);
  ASSERT_LT(le, 0.95 * dry);  // the water matters
  const EquilibriumPath r = run(p, e, coulomb(40));
  ASSERT_TRUE(r.fos_limit_point);
  EXPECT_NEAR(*r.fos_limit_point, le, 2 * kLimitStep);
  EXPECT_EQ(r.effects_used, (std::vector<std::string>{"gravity", "water"}));
}

TEST(EquilibriumPath, InsituStressClampsAWedge) {
  const blocks::Polyhedron p = wedge();
  const kinematics::Effects g = gravity();
  const EquilibriumPath dry = run(p, g, coulomb(30));
  const Eigen::Matrix3d hydrostatic = 0.2e6 * Eigen::Matrix3d::Identity();
  const EquilibriumPath clamped = run(p, g, coulomb(30), {}, hydrostatic);
  ASSERT_TRUE(dry.fos_limit_point && clamped.fos_limit_point);
  // 0.2 MPa on the joints: clamping outweighs the push of the excavated face.
  EXPECT_GT(*clamped.fos_limit_point, 1.1 * *dry.fos_limit_point);
  EXPECT_EQ(clamped.effects_used, (std::vector<std::string>{"gravity", "insitu_stress"}));
}

}  // namespace
}  // namespace rockface::mechanics
