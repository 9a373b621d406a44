// Whether a patch is a break or noise (break_significance.h): on a lining
// rougher than its predicted sigma, a shallow blob of that roughness that
// passed the threshold does not count and a break does; the spread around
// a patch is measured robustly (another break beside it does not inflate
// it); with too little lining around a patch its predicted sigma decides.
// The views are made here: their noise drawn from a seeded normal
// distribution of a known sigma, the patches given, not found.
#include "core/tunnel/break_significance.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace rockface::tunnel {
namespace {

struct View {
  std::size_t rows = 40, cols = 120;
  std::vector<std::int8_t> sign;
  std::vector<double> deviation, sigma;
  std::vector<std::uint8_t> valued;

  // White noise of `noise` sigma (seeded) where the lining is intact; every
  // cell's predicted sigma `predicted`.
  View(double noise, double predicted, unsigned seed)
      : sign(rows * cols, 0),
        deviation(rows * cols),
        sigma(rows * cols, predicted),
        valued(rows * cols, 1) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, noise);
    for (double& d : deviation) d = gauss(rng);
  }
  // A patch [r0, r1] x [c0, c1] of sign s, each cell `depth` deep (m,
  // positive) plus its noise.
  void patch(std::size_t r0, std::size_t r1, std::size_t c0, std::size_t c1, int s, double depth) {
    for (std::size_t r = r0; r <= r1; ++r)
      for (std::size_t c = c0; c <= c1; ++c) {
        const std::size_t k = r * cols + c % cols;
        sign[k] = static_cast<std::int8_t>(s);
        deviation[k] = s * (depth + std::abs(deviation[k]));
      }
  }
  int kept(const std::vector<std::int8_t>& out, int s) const {
    int n = 0;
    for (auto x : out) n += x == s ? 1 : 0;
    return n;
  }
};

BreakSignificanceOptions options() {
  BreakSignificanceOptions o;
  o.noise_sigmas = 2;
  o.ring_rows = 4;
  o.ring_cols = 20;
  return o;
}

TEST(BreakSignificance, ABlobAsDeepAsTheLiningIsRoughIsNoiseABreakIsNot) {
  // The lining's noise is 10 mm where 3 mm was predicted (a poorly textured
  // wall): a blob 5 sections by 11 rays that passed the predicted threshold
  // (2 x 3 mm) with a mean depth of about 14 mm (6 mm plus the noise's mean
  // absolute value, 0.8 x 10 mm; standard error over 55 cells 0.8 mm) is
  // within 2 x 10 mm (the spread measured to about 7 %: 1.4 mm), 3.7
  // standard errors; a break 60 mm deep is beyond it.
  View v(0.010, 0.003, 7);
  v.patch(5, 9, 10, 20, 1, 0.006);
  v.patch(25, 31, 60, 80, -1, 0.060);
  std::vector<PatchSignificance> decided;
  const auto out = significant_breaks(v.rows, v.cols, v.sign, v.deviation, v.valued, v.sigma,
                                      options(), &decided);
  EXPECT_EQ(v.kept(out, 1), 0);
  EXPECT_EQ(v.kept(out, -1), 7 * 21);
  ASSERT_EQ(decided.size(), 2u);
  for (const auto& p : decided) {
    ASSERT_TRUE(p.ring_sigma_m) << p.sign;
    // The spread of a few hundred cells of normal noise, measured by the
    // median absolute deviation: its standard error is about 1.1 / sqrt(n)
    // of sigma, 7 % for 250 cells; 20 % covers 3 of them.
    EXPECT_NEAR(*p.ring_sigma_m, 0.010, 0.2 * 0.010) << p.sign;
    EXPECT_NEAR(p.predicted_sigma_m, 0.003, 1e-12);
    EXPECT_EQ(p.counts, p.sign < 0) << p.mean_depth_m << " m deep, lining " << *p.ring_sigma_m;
  }
  // Where the lining is as smooth as predicted (3 mm), the same blob (6 mm
  // plus 0.8 x 3 mm, beyond 2 x 3 mm by 5 standard errors) counts: the rule
  // is the lining's roughness, not a fixed depth.
  View smooth(0.003, 0.003, 7);
  smooth.patch(5, 9, 10, 20, 1, 0.006);
  const auto kept = significant_breaks(smooth.rows, smooth.cols, smooth.sign, smooth.deviation,
                                       smooth.valued, smooth.sigma, options());
  EXPECT_EQ(smooth.kept(kept, 1), 5 * 11);
}

TEST(BreakSignificance, ABreakBesideAnotherIsMeasuredOnTheLiningNotOnTheOther) {
  // A second, deep break within the first one's ring: its cells are a
  // patch and are not part of the lining around the first, so the first
  // (30 mm on 4 mm noise) still counts, and the ring's spread stays the
  // noise's.
  View v(0.004, 0.004, 11);
  v.patch(10, 14, 20, 30, 1, 0.030);
  v.patch(10, 14, 34, 44, 1, 0.300);
  std::vector<PatchSignificance> decided;
  const auto out = significant_breaks(v.rows, v.cols, v.sign, v.deviation, v.valued, v.sigma,
                                      options(), &decided);
  EXPECT_EQ(v.kept(out, 1), 2 * 5 * 11);
  ASSERT_EQ(decided.size(), 2u);
  for (const auto& p : decided) {
    ASSERT_TRUE(p.ring_sigma_m);
    EXPECT_NEAR(*p.ring_sigma_m, 0.004, 0.2 * 0.004);  // as above
  }
}

TEST(BreakSignificance, WithLittleLiningAroundThePredictedSigmaDecides) {
  // A patch covering nearly all of a small view: fewer valued cells around
  // it than min_ring_cells; its mean depth (8 mm plus noise) is judged
  // against 2 x its predicted 3 mm and counts, and no ring sigma is told.
  View v(0.008, 0.003, 3);
  v.rows = 4;
  v.cols = 10;
  v.sign.assign(40, 0);
  v.deviation.resize(40);
  v.sigma.assign(40, 0.003);
  v.valued.assign(40, 1);
  v.patch(0, 3, 0, 7, 1, 0.008);
  std::vector<PatchSignificance> decided;
  const auto out = significant_breaks(v.rows, v.cols, v.sign, v.deviation, v.valued, v.sigma,
                                      options(), &decided);
  EXPECT_EQ(v.kept(out, 1), 32);
  ASSERT_EQ(decided.size(), 1u);
  EXPECT_FALSE(decided[0].ring_sigma_m);
}

TEST(BreakSignificance, SizesThatDoNotMatchAreRefused) {
  EXPECT_THROW(
      significant_breaks(2, 3, std::vector<std::int8_t>(6, 0), std::vector<double>(5, 0.0),
                         std::vector<std::uint8_t>(6, 1), std::vector<double>(6, 0.0), options()),
      InputError);
}

}  // namespace
}  // namespace rockface::tunnel
