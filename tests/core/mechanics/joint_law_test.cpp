// The joint law against closed forms at its stage boundaries, Barton's
// published peak friction angles, monotone / cyclic / CNS paths, a stiff
// joint, and bad parameters named in the error.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/mechanics/joint_law.h"
#include "core/mechanics/peak_strength.h"
#include "core/mechanics/shear_test.h"
#include "core/mechanics/staged_joint_law.h"

namespace rockface::mechanics {
namespace {

JointLawParameters barton(double jrc = 10, double kn = 1e10) {
  JointLawParameters p;
  p.model = JointModel::BartonBandis;
  p.jrc = jrc;
  p.jcs = 100e6;
  p.phi_b = deg_to_rad(30);
  p.normal_stiffness = kn;
  p.poisson_ratio = 0.25;
  return p;
}

std::vector<double> ramp(double from, double to, int n) {
  std::vector<double> u;
  for (int k = 1; k <= n; ++k) u.push_back(from + (to - from) * k / n);
  return u;
}

// Barton's parametric values of the peak friction angle phi_b + i,
// i = JRC log10(JCS / sigma_n), JCS = 100 MPa, phi_b = 30 degrees, as
// tabulated to 0.1 degree (Barton & Choubey 1977, Fig. 4 family).
struct PublishedPeak {
  double sigma_mpa, jrc, peak_deg;
};
constexpr PublishedPeak kPublished[] = {
    {0.5, 5, 41.5}, {0.5, 10, 53.0}, {0.5, 15, 64.5}, {1, 5, 40.0}, {1, 10, 50.0}, {1, 15, 60.0},
    {2, 5, 38.5},   {2, 10, 47.0},   {2, 15, 55.5},   {5, 5, 36.5}, {5, 10, 43.0}, {5, 15, 49.5}};

TEST(JointLaw, BartonPeakMatchesPublishedValues) {
  for (const auto& v : kPublished) {
    const BartonBandisPeak peak(barton(v.jrc));
    // The table is rounded to 0.1 degree: the formula must agree within half of that.
    EXPECT_NEAR(rad_to_deg(peak.peak_angle(v.sigma_mpa * 1e6)), v.peak_deg, 0.05)
        << "sigma_n " << v.sigma_mpa << " MPa, JRC " << v.jrc;
  }
}

TEST(JointLaw, ScaleCorrectionsFollowBartonBandis) {
  JointLawParameters p = barton(10);
  p.field_length = 1.0;  // ten times the 0.1 m sample
  const BartonBandisPeak peak(p);
  // JRC_n = 10 x 10^-0.2 = 6.3096, JCS_n = 1e8 x 10^-0.3 = 5.0119e7 (printed values to 5 digits).
  EXPECT_NEAR(peak.jrc(), 6.3096, 1e-4);
  EXPECT_NEAR(peak.jcs(), 5.0119e7, 1e3);
  // delta_p = Ln / 500 (JRC_n / Ln)^0.33 = 0.002 x 6.3096^0.33 = 3.674 mm.
  EXPECT_NEAR(peak.peak_displacement(), 3.674e-3, 1e-6);
  // A larger joint mobilises less roughness.
  EXPECT_LT(peak.peak_angle(1e6), BartonBandisPeak(barton(10)).peak_angle(1e6));
}

TEST(JointLaw, GrasselliPeakFollowsItsFormula) {
  JointLawParameters p = barton(10);
  p.model = JointModel::Grasselli;
  p.contact_area = 0.45;
  p.theta_max = deg_to_rad(70);
  p.roughness_c = 6;
  p.tensile_strength = 8e6;
  const GrasselliPeak peak(p);
  for (double s : {0.2e6, 1e6, 5e6}) {
    const double factor = 1 + std::exp(-70.0 / (9 * 0.45 * 7) * s / 8e6);
    const double expected = std::atan(factor * std::tan(deg_to_rad(30 + std::pow(70.0 / 6, 1.18))));
    // Same arithmetic in another order: rounding only.
    EXPECT_NEAR(peak.peak_angle(s), expected, 1e-12);
  }
  EXPECT_GT(peak.peak_angle(0.2e6), peak.peak_angle(5e6));  // strength envelope is concave
}

TEST(JointLaw, MonotoneCnlCurveMeetsTheClosedFormsAtEachStageBoundary) {
  const JointLawParameters p = barton(10);
  const auto law = make_joint_law(p);
  const auto& staged = dynamic_cast<const StagedJointLaw&>(*law);
  const double s = 1e6, ks = p.normal_stiffness / 2.5;
  const double tau_a = s * std::tan(deg_to_rad(30));
  const double tau_p = s * std::tan(deg_to_rad(50));  // JRC 10 at sigma_n = JCS / 100
  const double u_a = tau_a / ks, q = tau_p / ks;
  const double u_p = staged.peak().peak_displacement();
  ASSERT_GT(u_p, q) << "this joint must have a stage B";
  const ShearTestBoundary cnl{s, 0};
  // Stage A: elastic up to u_A, no dilation. The CNL driver holds sigma_n to
  // 1e-12 relative, so tractions are exact to ~1e-9 relative.
  auto a = shear_test(*law, cnl, {0.5 * u_a, u_a});
  EXPECT_NEAR(a[0].shear_stress, 0.5 * tau_a, 1e-9 * tau_a);
  EXPECT_EQ(a[0].stage, JointStage::Elastic);
  EXPECT_NEAR(a[1].shear_stress, tau_a, 1e-9 * tau_a);
  EXPECT_NEAR(a[1].opening, 0, 1e-15);
  // Stage B: the Bezier midpoint and the peak.
  const double u_mid = 0.25 * u_a + 0.5 * q + 0.25 * u_p;
  const double tau_mid = 0.25 * tau_a + 0.75 * tau_p;
  auto b = shear_test(*law, cnl, {u_a, u_mid, u_p});
  EXPECT_EQ(b[1].stage, JointStage::PrePeak);
  // Bisection of the slip to 1e-12 of the trial slip: ~1e-9 relative.
  EXPECT_NEAR(b[1].shear_stress, tau_mid, 1e-8 * tau_p);
  EXPECT_NEAR(b[2].shear_stress, tau_p, 1e-8 * tau_p);
  // Dilation at the peak: tan(d_p) kappa_p / 2, d_p = i / M = 20 / 2 degrees.
  const double kappa_p = u_p - q;
  EXPECT_NEAR(b[2].opening, std::tan(deg_to_rad(10)) * kappa_p / 2, 1e-9 * kappa_p);
  // Stage C: softening in the dissipated energy, towards the residual.
  auto c = shear_test(*law, cnl, ramp(0, 40 * u_p, 400));
  const double wc = 9 / std::numbers::ln2 * u_p * tau_p;
  EXPECT_NEAR(c.back().state.softening_energy, wc, 1e-8 * wc);
  double previous = tau_p;
  for (const auto& pt : c) {
    if (pt.shear < 1.01 * u_p) continue;
    EXPECT_EQ(pt.stage, JointStage::PostPeak);
    const double i = deg_to_rad(20) * std::exp(-pt.state.work / wc);
    EXPECT_NEAR(pt.shear_stress, s * std::tan(deg_to_rad(30) + i), 1e-8 * tau_p);
    EXPECT_LE(pt.shear_stress, previous + 1e-9 * tau_p);
    previous = pt.shear_stress;
  }
  EXPECT_LT(c.back().shear_stress, s * std::tan(deg_to_rad(35)));  // well on its way to residual
  EXPECT_GT(c.back().state.work, 0);
}

TEST(JointLaw, CyclicPathReversesAndDissipates) {
  const auto law = make_joint_law(barton(10));
  const double up = BartonBandisPeak(barton(10)).peak_displacement();
  std::vector<double> path = ramp(0, 3 * up, 60);
  for (double u : ramp(3 * up, -3 * up, 120)) path.push_back(u);
  for (double u : ramp(-3 * up, 0, 60)) path.push_back(u);
  const auto pts = shear_test(*law, {1e6, 0}, path);
  double forward_peak = 0, reverse_peak = 0, work = 0, max_opening = 0;
  for (size_t k = 0; k < pts.size(); ++k) {
    if (k < 60) forward_peak = std::max(forward_peak, pts[k].shear_stress);
    if (k >= 60 && k < 180) reverse_peak = std::min(reverse_peak, pts[k].shear_stress);
    if (k > 0)
      work +=
          0.5 * (pts[k].shear_stress + pts[k - 1].shear_stress) * (pts[k].shear - pts[k - 1].shear);
    EXPECT_GE(pts[k].opening, -1e-15);  // dilation never goes below the seated position
    EXPECT_LE(std::abs(pts[k].shear_stress), 1e6 * std::tan(deg_to_rad(50)) * (1 + 1e-9));
    max_opening = std::max(max_opening, pts[k].opening);
  }
  EXPECT_LT(reverse_peak, 0);                // the stress changes sign
  EXPECT_LT(-reverse_peak, forward_peak);    // the roughness worn forward is gone backward
  EXPECT_GT(work, 0);                        // a closed loop dissipates
  EXPECT_LT(pts[119].opening, max_opening);  // sliding back rides down the asperities
}

TEST(JointLaw, CnsRaisesTheNormalStressWithDilation) {
  const auto law = make_joint_law(barton(15));
  const double up = BartonBandisPeak(barton(15)).peak_displacement();
  const double k = 5e8;  // Pa/m, a stiff surrounding rock mass
  const auto pts = shear_test(*law, {1e6, k}, ramp(0, 2 * up, 80));
  for (const auto& pt : pts)
    EXPECT_NEAR(pt.normal_stress, 1e6 + k * pt.opening, 1e-6 * 1e6);  // held by bisection
  EXPECT_GT(pts.back().normal_stress, 1.05e6);
  // Higher normal stress: more shear strength than under CNL at the same slip.
  const auto cnl = shear_test(*law, {1e6, 0}, ramp(0, 2 * up, 80));
  EXPECT_GT(pts.back().shear_stress, cnl.back().shear_stress);
}

TEST(JointLaw, StiffJointStaysWellBehaved) {
  const auto law = make_joint_law(barton(10, 1e12));
  const double up = BartonBandisPeak(barton(10)).peak_displacement();
  const auto pts = shear_test(*law, {1e6, 0}, ramp(0, 2 * up, 100));
  double peak = 0;
  for (const auto& pt : pts) {
    ASSERT_TRUE(std::isfinite(pt.shear_stress));
    peak = std::max(peak, pt.shear_stress);
  }
  // The peak is still Barton's: 1e-8 relative from the bisections.
  EXPECT_NEAR(peak, 1e6 * std::tan(deg_to_rad(50)), 1e-3 * 1e6);
}

TEST(JointLaw, CoulombIsElasticPerfectlyPlastic) {
  JointLawParameters p;
  p.model = JointModel::Coulomb;
  p.friction = deg_to_rad(35);
  p.cohesion = 2e4;
  p.normal_stiffness = 1e12;
  const auto law = make_joint_law(p);
  const auto pts = shear_test(*law, {5e5, 0}, ramp(0, 1e-3, 20));
  const double limit = 2e4 + 5e5 * std::tan(deg_to_rad(35));
  EXPECT_NEAR(pts.back().shear_stress, limit, 1e-9 * limit);
  EXPECT_NEAR(pts.back().opening, 0, 1e-15);  // no dilation
  // Strength reduction divides it.
  const JointResponse r = law->respond({}, 5e5 / 1e12, Eigen::Vector2d(1e-3, 0), 2.0);
  EXPECT_NEAR(r.shear_stress.norm(), limit / 2, 1e-9 * limit);
  // Open joint: no tractions.
  EXPECT_EQ(law->respond({}, -1e-6, Eigen::Vector2d(1e-3, 0), 1.0).stage, JointStage::Open);
}

TEST(JointLaw, BadParametersAreNamed) {
  auto where = [](const JointLawParameters& p) {
    try {
      make_joint_law(p);
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string("accepted");
  };
  JointLawParameters p = barton();
  p.normal_stiffness = -1e10;
  EXPECT_EQ(where(p), "joint_law.normal_stiffness");
  p = barton(25);
  EXPECT_EQ(where(p), "joint_law.jrc");
  p = barton();
  p.jcs = 0;
  EXPECT_EQ(where(p), "joint_law.jcs");
  p = barton();
  p.poisson_ratio = 0.6;
  EXPECT_EQ(where(p), "joint_law.poisson_ratio");
  p = barton();
  p.model = JointModel::Grasselli;
  p.contact_area = 1.5;
  EXPECT_EQ(where(p), "joint_law.contact_area");
  EXPECT_EQ(where(barton()), "accepted");
}

}  // namespace
}  // namespace rockface::mechanics
