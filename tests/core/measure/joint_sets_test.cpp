// Fisher statistics against closed forms and a published worked example;
// clustering of a sampled mixture of three sets; spacing and trace length.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/joint_sets.h"

namespace rm = rockface::measure;
namespace rg = rockface::geometry;
using rockface::deg_to_rad;
using rockface::rad_to_deg;

namespace {

// A sample of a Fisher distribution about `mean` (exact inversion of the
// distribution of the angle from the mean).
std::vector<Eigen::Vector3d> fisher_sample(const Eigen::Vector3d& mean, double kappa, int n,
                                           std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const Eigen::Vector3d m = mean.normalized(), a = m.unitOrthogonal(), b = m.cross(a);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i) {
    const double c = 1 + std::log(1 - u(rng) * (1 - std::exp(-2 * kappa))) / kappa;
    const double s = std::sqrt(std::max(0.0, 1 - c * c)), phi = 2 * rockface::kPi * u(rng);
    Eigen::Vector3d d = c * m + s * (std::cos(phi) * a + std::sin(phi) * b);
    if (i % 3 == 0) d = -d;  // poles are axes: the sense must not matter
    out.push_back(d);
  }
  return out;
}

Eigen::Vector3d pole(double dip, double dipdir) {
  return rg::plane_normal_deg(dip, dipdir);
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

}  // namespace

TEST(Fisher, TwoPolesClosedForm) {
  // Two unit vectors 2t apart: R = 2 cos t, K = 1 / (2 - R), mean the bisector,
  // cos a95 = 1 - (2 - R) / R (20 - 1).
  const double t = deg_to_rad(10);
  const Eigen::Vector3d a(std::sin(t), 0, std::cos(t)), b(-std::sin(t), 0, std::cos(t));
  const auto f = rm::fisher_statistics({a, -b});
  EXPECT_NEAR(f.resultant, 2 * std::cos(t), 1e-12);
  EXPECT_NEAR(f.kappa, 1 / (2 - 2 * std::cos(t)), 1e-9);
  EXPECT_LT((f.mean - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  const double R = 2 * std::cos(t);
  EXPECT_NEAR(f.alpha95, std::acos(1 - (2 - R) / R * 19), 1e-12);
}

TEST(Fisher, IdenticalPolesHaveInfiniteKappaAndNoCone) {
  const auto f = rm::fisher_statistics({pole(30, 120), pole(30, 120), -pole(30, 120)});
  EXPECT_TRUE(std::isinf(f.kappa));
  EXPECT_NEAR(f.alpha95, 0, 1e-6);
  EXPECT_NEAR(rad_to_deg(f.plane().dip), 30, 1e-9);
  EXPECT_NEAR(rad_to_deg(f.plane().dipdir), 120, 1e-9);
}

TEST(Fisher, PmagPyWorkedExample) {
  // PmagPy documentation, ipmag.fisher_mean example (Tauxe et al., PmagPy):
  // declinations 140, 127, 142, 136 and inclinations 21, 23, 19, 22 give
  // mean 136.3/21.3, R = 3.98121, k = 159.69, alpha95 = 7.29 deg.
  std::vector<Eigen::Vector3d> d;
  const double dec[] = {140, 127, 142, 136}, inc[] = {21, 23, 19, 22};
  for (int i = 0; i < 4; ++i)
    d.push_back(rg::line_direction({deg_to_rad(dec[i]), deg_to_rad(inc[i])}));
  const auto f = rm::fisher_statistics(d);
  EXPECT_NEAR(f.resultant, 3.9812138971889026, 1e-9);
  EXPECT_NEAR(f.kappa, 159.69251473636305, 1e-6);
  EXPECT_NEAR(rad_to_deg(f.alpha95), 7.292891411309177, 1e-6);
  const Eigen::Vector3d expected =
      rg::line_direction({deg_to_rad(136.30838974272072), deg_to_rad(21.34778402689999)});
  EXPECT_LT(angle_deg(f.mean, expected), 1e-6);
}

TEST(Fisher, SampledKappaIsRecovered) {
  std::mt19937 rng(11);
  const auto poles = fisher_sample(pole(55, 250), 40, 2000, rng);
  const auto f = rm::fisher_statistics(poles);
  // The estimate's relative standard error is ~1 / sqrt(N) ~ 2 %.
  EXPECT_NEAR(f.kappa, 40, 40 * 0.08);
  // a95 ~ 140 deg / sqrt(K N) = 0.5 deg: the mean is inside a few of it.
  EXPECT_LT(angle_deg(f.mean, pole(55, 250)), 3 * rad_to_deg(f.alpha95));
  EXPECT_NEAR(rad_to_deg(f.alpha95), 140 / std::sqrt(40.0 * 2000), 0.1);
}

TEST(Fisher, BadPolesAreRefused) {
  EXPECT_THROW(rm::fisher_statistics({}), rockface::InputError);
  EXPECT_THROW(rm::fisher_statistics({Eigen::Vector3d(std::nan(""), 0, 1)}), rockface::InputError);
  EXPECT_THROW(rm::fisher_statistics({Eigen::Vector3d::Zero()}), rockface::InputError);
}

TEST(Clustering, ThreeSetMixtureIsRecoveredAutomatically) {
  std::mt19937 rng(7);
  const Eigen::Vector3d truth[3] = {pole(60, 200), pole(75, 110), pole(20, 350)};
  const int sizes[3] = {60, 40, 30};
  std::vector<Eigen::Vector3d> poles;
  std::vector<int> truth_set;
  for (int s = 0; s < 3; ++s)
    for (const auto& p : fisher_sample(truth[s], 30, sizes[s], rng)) {
      poles.push_back(p);
      truth_set.push_back(s);
    }
  for (int count : {0, 3}) {
    rm::ClusterOptions options;
    options.count = count;
    const auto c = rm::cluster_poles(poles, options);
    ASSERT_EQ(c.sets.size(), 3u) << "count " << count;
    // Ordered by size: the largest set is set 0 of the truth, and so on.
    for (int s = 0; s < 3; ++s) {
      // K = 30 with 30-60 poles: a95 ~ 140 / sqrt(K N) ~ 3.3-4.7 deg.
      EXPECT_LT(angle_deg(c.sets[s].mean, truth[s]), 5.0) << "set " << s;
      // 2 (N - 1) K / K_est follows chi-square with 2N - 2 degrees of
      // freedom: for N = 30 its 0.05 % and 99.95 % points put K_est within
      // 0.6 K .. 1.96 K.
      EXPECT_GT(c.sets[s].kappa, 0.55 * 30);
      EXPECT_LT(c.sets[s].kappa, 2.0 * 30);
    }
    int wrong = 0;
    for (std::size_t i = 0; i < poles.size(); ++i) wrong += c.set_of[i] != truth_set[i];
    // Sets 50+ degrees apart with ~10 deg spread: the tails barely overlap.
    EXPECT_LE(wrong, 3);
  }
}

TEST(Clustering, OneSetStaysOneSet) {
  std::mt19937 rng(2);
  const auto poles = fisher_sample(pole(45, 45), 25, 80, rng);
  const auto c = rm::cluster_poles(poles, {});
  EXPECT_EQ(c.sets.size(), 1u);
}

TEST(JointSets, SpacingTraceLengthAndCensoring) {
  // Four parallel joints 0.5 m apart (one mapped twice), traces 2, 3, 4 m
  // and one censored at 1.5 m.
  std::vector<rm::SetMember> members;
  const Eigen::Vector3d n = pole(60, 200);
  const double offsets[] = {0.0, 0.5, 0.5 + 0.01, 1.0, 1.5};
  const double lengths[] = {2.0, 3.0, 3.0, 4.0, 1.5};
  for (int i = 0; i < 5; ++i) {
    rm::SetMember m;
    m.normal = n;
    m.point = offsets[i] * n + Eigen::Vector3d(0.3 * i, -0.2 * i, 0).cross(n);
    m.trace_length = lengths[i];
    m.censored = i == 4;
    members.push_back(m);
  }
  const auto clusters = rm::cluster_poles(std::vector<Eigen::Vector3d>(5, n), {});
  rm::ScanLine line{-n * 1.0 + Eigen::Vector3d(0, 0, 0), n * 3.0};
  const auto sets = rm::summarise_joint_sets(members, clusters, line);
  ASSERT_EQ(sets.size(), 1u);
  ASSERT_TRUE(sets[0].spacing);
  EXPECT_NEAR(*sets[0].spacing, 0.5, 1e-9);
  EXPECT_EQ(sets[0].spacing_gaps, 3);
  ASSERT_TRUE(sets[0].scanline_spacing);  // the line runs along the normal
  EXPECT_NEAR(*sets[0].scanline_spacing, 0.5, 1e-9);
  EXPECT_EQ(sets[0].traces, 5);
  EXPECT_EQ(sets[0].censored_traces, 1);
  EXPECT_NEAR(*sets[0].mean_trace_length, 13.5 / 5, 1e-12);
  EXPECT_NEAR(*sets[0].mean_uncensored_trace_length, 3.0, 1e-12);
  EXPECT_NEAR(*sets[0].persistence, 3.0, 1e-12);
  EXPECT_NE(sets[0].censoring.find("1 of 5"), std::string::npos);
}

TEST(Fisher, Alpha95FromKAndCountIsTheWorkedExamplesCone) {
  // The PmagPy example above kept only as a stored set keeps it: K = 159.69
  // of N = 4 poles. R = N - (N - 1) / K = 3.98121 again, so alpha95 = 7.29
  // deg (Tauxe et al.); 1e-6 deg: K is given to the digits PmagPy prints.
  EXPECT_NEAR(rad_to_deg(rm::alpha95_from(159.69251473636305, 4)), 7.292891411309177, 1e-6);
  // Undefined for fewer than two poles or no concentration; a point for K infinite.
  EXPECT_EQ(rm::alpha95_from(50, 1), rockface::kPi);
  EXPECT_EQ(rm::alpha95_from(0, 10), rockface::kPi);
  EXPECT_EQ(rm::alpha95_from(std::numeric_limits<double>::infinity(), 10), 0);
}

TEST(Fisher, VariabilityConeHoldsItsFractionOfTheDistribution) {
  // P(angle <= t) = (1 - exp(-K (1 - cos t))) / (1 - exp(-2 K)); for K = 100
  // exp(-200) vanishes and 95 % lie within 1 - cos t = ln(20) / 100:
  // t = 14.07 deg. 1e-9: closed form against closed form.
  EXPECT_NEAR(rm::fisher_cone(100), std::acos(1 - std::log(20.0) / 100), 1e-9);
  // Fisher's 63 % cone is about 81 deg / sqrt(K) for a concentrated set
  // (Butler 1992, Paleomagnetism, 6.2): K = 400 gives 4.05 deg; the rule
  // is an approximation good to 0.1 % here (1 - cos t ~ t^2 / 2).
  EXPECT_NEAR(rad_to_deg(rm::fisher_cone(400, 1 - std::exp(-1.0))), 81 / std::sqrt(400.0), 0.005);
  // A set spread over the sphere (K -> 0) has no cone; a point has a point.
  EXPECT_EQ(rm::fisher_cone(0), rockface::kPi);
  EXPECT_EQ(rm::fisher_cone(std::numeric_limits<double>::infinity()), 0);
  // Monte Carlo: poles drawn from Fisher's distribution (inverse CDF of
  // cos t) fall inside the cone at its fraction, to within 3 binomial sigma
  // of 20000 draws (0.46 %).
  const double kappa = 20;
  const double t95 = rm::fisher_cone(kappa);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u01(0, 1);
  int inside = 0;
  const int draws = 20000;
  for (int i = 0; i < draws; ++i) {
    const double u = u01(random);
    const double cos_t = 1 + std::log(u + (1 - u) * std::exp(-2 * kappa)) / kappa;
    inside += cos_t >= std::cos(t95);
  }
  EXPECT_NEAR(static_cast<double>(inside) / draws, 0.95, 3 * std::sqrt(0.95 * 0.05 / draws));
}
