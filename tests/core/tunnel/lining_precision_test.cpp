// Issue 38: each cell's predicted depth precision from its own distance and
// incidence (core/tunnel/lining_precision.h), against figures worked by hand
// from the formula's derivation: a pair 1.4 m apart along x, the left camera
// at the origin looking along +y, f = 800 px, sigma_d = 0.3 px, a 5 px window.
#include <cmath>

#include <gtest/gtest.h>

#include "core/tunnel/lining_precision.h"

namespace rockface::tunnel {
namespace {

LiningPrecision one_pair() {
  StereoPairView pair;
  pair.left_centre = {0, 0, 0};
  pair.right_centre = {1.4, 0, 0};
  pair.optical_axis = {0, 1, 0};
  pair.focal_px = 800;
  pair.disparity_sigma_px = 0.3;
  pair.window_px = 5;
  return {{pair}};
}

// Rounding only: the figures below are worked to 1e-9 m.
constexpr double kWorkedM = 1e-9;

TEST(LiningPrecision, ASurfaceFacingTheCamerasHasTheNormalCasesDepthPrecision) {
  // Z = r = 10 m, seen square on, normal across the base: Z^2 sigma_d / (f B)
  // = 100 * 0.3 / 1120 m, the face's own figure, and no slant term.
  const auto s = predicted_normal_sigma(one_pair(), {0, 10, 0}, {0, -1, 0});
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, 30.0 / 1120.0, kWorkedM);
}

TEST(LiningPrecision, AWallAlongTheDriveAddsTheWindowsFootprintAtItsDepth) {
  // The right wall at x = 3, 6 m ahead: r = sqrt(45), cos i = 3 / sqrt(45),
  // normal along the base. Matching: 0.3 * sqrt(45) * 6 * (3 / sqrt(45)) /
  // 1120 = 5.4 / 1120 m; slant: 5 * 6 * 1 / (sqrt(12) * 800) m.
  const auto s = predicted_normal_sigma(one_pair(), {3, 6, 0}, {1, 0, 0});
  ASSERT_TRUE(s.has_value());
  const double matching = 5.4 / 1120.0, slant = 30.0 / (std::sqrt(12.0) * 800.0);
  EXPECT_NEAR(*s, std::sqrt(matching * matching + slant * slant), kWorkedM);
  // The wall is less precise than the same depth seen square on.
  EXPECT_GT(*s, 36 * 0.3 / 1120.0);
}

TEST(LiningPrecision, TheInvertSeenAtGrazingIsAsPreciseAsItsProjectedDepthError) {
  // The invert 1.5 m below, 6 m ahead: normal across the base (no slant
  // term), cos i = 1.5 / sqrt(38.25): 0.3 * sqrt(38.25) * 6 * 1.5 /
  // sqrt(38.25) / 1120 = 2.7 / 1120 m.
  const auto s = predicted_normal_sigma(one_pair(), {0, 6, -1.5}, {0, 0, -1});
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, 2.7 / 1120.0, kWorkedM);
}

TEST(LiningPrecision, TheBestPairIsTakenAndAPointBehindEveryCameraHasNone) {
  LiningPrecision two = one_pair();
  StereoPairView nearer = two.pairs.front();
  nearer.left_centre = {0, 5, 0};  // the same pair 5 m further along
  nearer.right_centre = {1.4, 5, 0};
  two.pairs.push_back(nearer);
  const auto s = predicted_normal_sigma(two, {0, 10, 0}, {0, -1, 0});
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, 25 * 0.3 / 1120.0, kWorkedM);  // Z = 5 m from the nearer pair
  EXPECT_FALSE(predicted_normal_sigma(one_pair(), {0, -2, 0}, {0, 1, 0}).has_value());
}

}  // namespace
}  // namespace rockface::tunnel
