// The consistent tangents that path following uses instead of differences:
// each joint law's d(tractions) / d(closure, shear) and d / d(divisor) in
// every stage, and the block's d unbalance / d(motion, load factor,
// divisor) with rotations and a follower load, against central
// differences of the responses themselves.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/blocks/mass_properties.h"
#include "core/common/units.h"
#include "core/kinematics/effects/effect_water.h"
#include "core/mechanics/block_equilibrium.h"
#include "core/mechanics/block_loads.h"
#include "core/mechanics/contact_points.h"
#include "core/mechanics/joint_law.h"
#include "core/mechanics/peak_strength.h"
#include "tests/support/mechanics_blocks.h"

namespace rockface::mechanics {
namespace {

using namespace testing;

Eigen::Vector3d tractions(const JointResponse& r) {
  return {r.normal_stress, r.shear_stress(0), r.shear_stress(1)};
}

// Central differences of the response in (closure, shear) with step h (m),
// and in the divisor with step hd.
struct Differences {
  Eigen::Matrix3d tangent;
  Eigen::Vector3d divisor_rate;
};
Differences differences(const JointLaw& law, const JointState& s, double closure,
                        const Eigen::Vector2d& shear, double divisor, double h, double hd) {
  Differences d;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e(k) = h;
    const auto plus = law.respond(s, closure + e(0), shear + e.tail<2>(), divisor);
    const auto minus = law.respond(s, closure - e(0), shear - e.tail<2>(), divisor);
    d.tangent.col(k) = (tractions(plus) - tractions(minus)) / (2 * h);
  }
  d.divisor_rate = (tractions(law.respond(s, closure, shear, divisor + hd)) -
                    tractions(law.respond(s, closure, shear, divisor - hd))) /
                   (2 * hd);
  return d;
}

// A committed state reached by shearing the joint along x under a
// constant closure in n steps up to `slip` of total shear displacement.
JointState sheared(const JointLaw& law, double closure, double shear, int n) {
  JointState s;
  for (int k = 1; k <= n; ++k)
    s = law.respond(s, closure, Eigen::Vector2d(shear * k / n, 0), 1.0).state;
  return s;
}

TEST(ConsistentTangent, StagedLawMatchesDifferencesInEveryStage) {
  for (const double kn : {1e10, 1e12}) {
    const JointLawParameters p = barton(10, kn);
    const auto law = make_joint_law(p);
    const double up = BartonBandisPeak(p).peak_displacement();
    const double closure = 3e4 / kn;  // 30 kPa, a few metres of rock
    struct Case {
      const char* stage;
      JointState committed;
      Eigen::Vector2d shear;
      JointStage expected;
    };
    // Shear increments that slip in stage B, cross the peak, and soften
    // after it; the second component turns the trial off the slip's axis.
    const JointState b = sheared(law.operator*(), closure, 0.3 * up, 10);
    const JointState c = sheared(law.operator*(), closure, 2.0 * up, 40);
    const std::vector<Case> cases{
        {"elastic", {}, Eigen::Vector2d(1e3 / kn, 0), JointStage::Elastic},
        {"pre-peak", b, Eigen::Vector2d(0.35 * up, 0.02 * up), JointStage::PrePeak},
        {"crossing the peak", b, Eigen::Vector2d(1.2 * up, 0.05 * up), JointStage::PostPeak},
        {"post-peak", c, Eigen::Vector2d(2.1 * up, 0.05 * up), JointStage::PostPeak}};
    for (const Case& k : cases) {
      const double cl = closure;
      const JointResponse r = law->respond(k.committed, cl, k.shear, 1.5);
      ASSERT_EQ(r.stage, k.expected) << k.stage << " at " << kn;
      ASSERT_GT(r.normal_stress, 0) << k.stage;
      // Steps of 1 Pa / kn stay inside one branch of the law; central
      // differences are then exact to ~(1 Pa / 30 kPa)^2 of the curvature
      // and ~1e-16 x 3e4 Pa / h of rounding (~3e-12 kn): 1e-6 of ks is far
      // above both and far below any error in a derivative.
      const double h = 1.0 / kn;
      const Differences d = differences(*law, k.committed, cl, k.shear, 1.5, h, 1e-7);
      const double ks = law->shear_stiffness();
      EXPECT_LT((r.tangent - d.tangent).norm(), 1e-6 * ks * 3)
          << k.stage << " at " << kn << "\nanalytic\n"
          << r.tangent << "\ndifferences\n"
          << d.tangent;
      // d / d divisor: tractions ~ strength / divisor^2 ~ 1e4 Pa; 1e-6 of it.
      EXPECT_LT((r.divisor_rate - d.divisor_rate).norm(), 1e-6 * 1e4 + 1e-6 * d.divisor_rate.norm())
          << k.stage << " at " << kn << "\n"
          << r.divisor_rate.transpose() << "\n"
          << d.divisor_rate.transpose();
    }
  }
}

TEST(ConsistentTangent, CoulombLawMatchesDifferences) {
  const auto law = make_joint_law(coulomb(35, 2e4, 1e10));
  const double closure = 5e5 / 1e10;
  for (const Eigen::Vector2d& shear : {Eigen::Vector2d(1e-6, 0), Eigen::Vector2d(1e-3, 4e-4)}) {
    const JointResponse r = law->respond({}, closure, shear, 1.3);
    // Linear in each branch: differences of 1e-10 m are exact to rounding
    // (~1e-16 x 4e5 Pa / 1e-10 m = 4e-1 Pa/m against ks = 4e9).
    const Differences d = differences(*law, {}, closure, shear, 1.3, 1e-10, 1e-7);
    EXPECT_LT((r.tangent - d.tangent).norm(), 1e-6 * law->shear_stiffness());
    EXPECT_LT((r.divisor_rate - d.divisor_rate).norm(), 1e-2);
  }
}

TEST(ConsistentTangent, BlockJacobianMatchesDifferences) {
  // A slab with a water table (a follower load on its joint face), turned
  // and shifted so that every contact slips in stage B of a 1e12 Pa/m
  // Barton-Bandis joint.
  Slab slab;
  const blocks::Polyhedron p = slab.block();
  kinematics::Effects e = gravity();
  e.push_back(std::make_unique<kinematics::WaterEffect>(
      9810, slab.at(0.5, 0.5, 0) + Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ()));
  const blocks::MassProperties m = blocks::mass_properties(p, 2600);
  const BlockEquilibrium eq(p, m, contact_points(p, 2), laws(p, barton(10, 1e12)),
                            block_loads(p, m, e), std::nullopt);
  const double up = BartonBandisPeak(barton(10, 1e12)).peak_displacement();
  Vector6 x;
  x << 0.2 * up * slab.d() - 2e-8 * slab.n(), 1e-9 * Eigen::Vector3d(1, -2, 0.5);
  UnbalanceDerivatives a;
  std::vector<JointResponse> responses;
  eq.unbalance(x, 0.9, 1.4, &responses, &a);
  for (const JointResponse& r : responses) ASSERT_TRUE(r.slipping);
  // Steps of 1e-12 m (and 1e-12 rad, ~1e-12 m at the contacts): inside
  // the slipping branch of every contact; rounding of the unbalance
  // (~1e-16 x 1e12 Pa/m x 1e-8 m x 12 m^2 ~ 1e-3 N) over 1e-12 gives 1e9
  // N/m against entries of ~1e12 x 12: 1e-3 of the largest entry.
  Matrix6 d;
  const double h = 1e-12;
  for (int k = 0; k < 6; ++k) {
    Vector6 e6 = Vector6::Zero();
    e6(k) = h;
    d.col(k) = (eq.unbalance(x + e6, 0.9, 1.4) - eq.unbalance(x - e6, 0.9, 1.4)) / (2 * h);
  }
  EXPECT_LT((a.motion - d).norm(), 1e-3 * d.norm()) << "analytic\n"
                                                    << a.motion << "\ndifferences\n"
                                                    << d;
  // Load factor and divisor: smooth, steps of 1e-6.
  const Vector6 dl = (eq.unbalance(x, 0.9 + 1e-6, 1.4) - eq.unbalance(x, 0.9 - 1e-6, 1.4)) / 2e-6;
  const Vector6 dd = (eq.unbalance(x, 0.9, 1.4 + 1e-6) - eq.unbalance(x, 0.9, 1.4 - 1e-6)) / 2e-6;
  EXPECT_LT((a.load_factor - dl).norm(), 1e-5 * dl.norm()) << a.load_factor.transpose() << "\n"
                                                           << dl.transpose();
  EXPECT_LT((a.divisor - dd).norm(), 1e-5 * dd.norm()) << a.divisor.transpose() << "\n"
                                                       << dd.transpose();
}

}  // namespace
}  // namespace rockface::mechanics
