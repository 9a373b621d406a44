// Cones with half-spaces on both sides of (nearly) parallel planes, decided
// within the planes' common plane (core/geometry/parallel_planes.h), against
// margins worked by hand.
#include "core/geometry/parallel_planes.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace rockface::geometry {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// A direction at `deg` from +x toward +z (in the plane y = 0).
Eigen::Vector3d in_xz(double deg) {
  return {std::cos(deg * kDeg), 0, std::sin(deg * kDeg)};
}

TEST(ParallelPlanes, ASlabOpenWithinItsPlaneIsOpenByTheAngleThere) {
  // Both sides of y = 0, the second turned by 1e-4 rad about x (the slab's
  // planes converge toward +z), and two half-spaces whose normals lie in
  // the plane y = 0 at 60 and 120 degrees from +x toward +z: within the
  // plane the directions 30 to 150 degrees from +x keep to both, open by
  // cos(30 degrees) = sin(60 degrees) about their bisector +z: 60 degrees.
  // The ordinary margin is the hair between the slab's planes.
  const double tilt = 1e-4;
  const std::vector<Eigen::Vector3d> n{Eigen::Vector3d::UnitY(),
                                       -Eigen::Vector3d(0, std::cos(tilt), std::sin(tilt)),
                                       in_xz(60), in_xz(120)};
  const auto pairs = opposite_pairs(n, 1 * kDeg);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], (std::pair<int, int>{0, 1}));
  EXPECT_LE(std::abs(Cone(n).margin().angle), tilt);
  const ParallelReduction r = parallel_reduction(n, pairs, 1 * kDeg);
  ASSERT_EQ(r.axes.size(), 1u);
  EXPECT_NEAR(r.widest, tilt, 1e-12);  // acos of a cosine near 1: ~1e-12 rad
  const ConeMargin m = margin_with_parallel_planes(n, r);
  // Within the plane normal to the bisecting axis (y turned by tilt / 2),
  // n . d for d = +z turned by tilt / 2: cos(30 deg) x cos(tilt / 2).
  EXPECT_NEAR(m.angle, 60 * kDeg, 1e-8);
  EXPECT_NEAR(m.direction.z(), 1, 1e-8);
}

TEST(ParallelPlanes, ASlabShutWithinItsPlaneIsShutByTheAngleThere) {
  // Both sides of y = 0, of x = 0 and of z = 0.
  const std::vector<Eigen::Vector3d> n{Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(),
                                       Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                       Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};
  // Three pairs of planes that share no line leave the origin alone: the
  // ordinary margin, -max(|d_x|, |d_y|, |d_z|) at its largest for d along
  // a diagonal of the octants: shut by asin(1 / sqrt 3).
  const ParallelReduction all = parallel_reduction(n, opposite_pairs(n, kDeg), kDeg);
  EXPECT_EQ(all.axes.size(), 3u);
  EXPECT_NEAR(margin_with_parallel_planes(n, all).angle, -std::asin(std::sqrt(1.0 / 3)), 1e-12);
  // The slab of y = 0 alone taken as parallel: d = (cos p, 0, sin p) in its
  // plane has min(cos p, -cos p, sin p, -sin p) = -max(|cos p|, |sin p|),
  // at its largest for p = 45 degrees: shut by 45 degrees.
  const ParallelReduction slab = parallel_reduction(n, {{0, 1}}, kDeg);
  ASSERT_EQ(slab.axes.size(), 1u);
  EXPECT_NEAR(margin_with_parallel_planes(n, slab).angle, -45 * kDeg, 1e-12);
}

TEST(ParallelPlanes, TwoSlabsLeaveTheLineTheyShare) {
  // Slabs y and x: the cone lies on the z axis; a half-space of normal
  // (0, 0, 1) turned 30 degrees toward +x keeps +z at 60 degrees inside.
  const std::vector<Eigen::Vector3d> n{Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(),
                                       Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                       in_xz(60)};
  const ParallelReduction r = parallel_reduction(n, opposite_pairs(n, kDeg), kDeg);
  ASSERT_EQ(r.axes.size(), 2u);
  const ConeMargin m = margin_with_parallel_planes(n, r);
  EXPECT_NEAR(m.angle, 60 * kDeg, 1e-12);
  EXPECT_NEAR(m.direction.z(), 1, 1e-12);
  // Nothing else: any direction of the line, open by 90 degrees.
  const std::vector<Eigen::Vector3d> only(n.begin(), n.begin() + 4);
  EXPECT_NEAR(
      margin_with_parallel_planes(only, parallel_reduction(only, {{0, 1}, {2, 3}}, kDeg)).angle,
      90 * kDeg, 1e-12);
}

TEST(ParallelPlanes, PlanesFurtherApartThanTheToleranceAreNoPair) {
  const std::vector<Eigen::Vector3d> n{Eigen::Vector3d::UnitY(),
                                       -Eigen::Vector3d(0, std::cos(2 * kDeg), std::sin(2 * kDeg))};
  EXPECT_TRUE(opposite_pairs(n, 1 * kDeg).empty());
  EXPECT_EQ(opposite_pairs(n, 3 * kDeg).size(), 1u);
}

}  // namespace
}  // namespace rockface::geometry
