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
#include "core/mechanics/contact_points.h"
#include "core/mechanics/equilibrium_path.h"
#include "tests/core/mechanics/mechanics_blocks.h"

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
