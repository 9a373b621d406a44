// The pieces of the block mechanics on their own: the Euler-parameter
// rotation, contact points, and the classification of (K + p^2 M) z = 0.
#include <cmath>

#include <gtest/gtest.h>

#include "core/mechanics/block_equilibrium.h"
#include "core/mechanics/contact_points.h"
#include "core/mechanics/stability_analysis.h"
#include "tests/support/mechanics_blocks.h"

namespace rockface::mechanics {
namespace {

TEST(RigidRotation, OffsetMatchesAngleAxisAtLargeAndTinyAngles) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Vector3d r(0.3, 1.7, -2.2);
  for (double angle : {1e-14, 1e-9, 1e-4, 0.3, 2.5}) {
    const Eigen::Vector3d expected = Eigen::AngleAxisd(angle, axis) * r - r;
    const Eigen::Vector3d got = rotation_offset(rotation_quaternion(angle * axis), r);
    // R r - r from Eigen cancels at tiny angles (error ~1e-16 |r|); the
    // quaternion form keeps full relative precision: compare to the first
    // order rotation there (which leaves out angle^2 |r| / 2), to 1e-12
    // relative otherwise.
    if (angle < 1e-6)
      EXPECT_LT((got - angle * axis.cross(r)).norm(), (1e-12 * angle + angle * angle) * r.norm())
          << angle;
    else
      EXPECT_LT((got - expected).norm(), 1e-12 * r.norm()) << angle;
  }
  EXPECT_NEAR(rotation_quaternion(axis * 2.5).norm(), 1.0, 1e-15);
}

TEST(ContactPoints, CoverTheJointFacesWithTheirArea) {
  testing::Slab slab;  // 4 x 3 m base on J1, every other face free
  for (int density : {1, 2, 5}) {
    const auto contacts = contact_points(slab.block(), density);
    // Two triangles on the base, density^2 sub-triangles each.
    EXPECT_EQ(contacts.size(), static_cast<size_t>(2 * density * density));
    double area = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& c : contacts) {
      area += c.area;
      centre += c.area * c.position;
      EXPECT_NEAR(c.normal.dot(slab.n()), 1.0, 1e-12);  // from the joint into the block
      EXPECT_NEAR(c.t1.cross(c.t2).dot(c.normal), 1.0, 1e-12);
    }
    // Exact: sub-triangle areas sum to the face; the midpoint rule is
    // exact for the centroid (a linear function).
    EXPECT_NEAR(area, 12.0, 1e-12);
    EXPECT_LT((centre / area - slab.at(0.5, 0.5, 0)).norm(), 1e-12);
  }
}

TEST(StabilityAnalysis, StableDivergenceAndFlutter) {
  const Matrix6 m = Matrix6::Identity() * 2;
  // Symmetric positive definite: every p^2 = -mu < 0, bounded oscillation.
  Matrix6 k = Matrix6::Identity() * 10;
  EXPECT_EQ(stability_analysis(k, m, 1).kind, StabilityKind::Stable);
  // A negative stiffness along one rotation: divergence in that mode.
  k(5, 5) = -3;
  StabilityAnalysis s = stability_analysis(k, m, 1);
  EXPECT_EQ(s.kind, StabilityKind::Divergence);
  EXPECT_NEAR(s.mu.front().real(), -1.5, 1e-12);
  EXPECT_GT(std::abs(s.dynamic_mode(5)), 0.99 * s.dynamic_mode.norm());
  // A circulatory (follower-type) coupling of two translations: mu = 5 +- 2i,
  // a complex pair, flutter.
  k = Matrix6::Identity() * 10;
  k(0, 1) = 4;
  k(1, 0) = -4;
  s = stability_analysis(k, m, 1);
  EXPECT_EQ(s.kind, StabilityKind::Flutter);
  EXPECT_TRUE(s.critical_complex);
  EXPECT_NEAR(std::abs(s.mu.front().imag()), 2.0, 1e-12);
  // Singular K: the static mode is its null vector.
  k = Matrix6::Identity();
  k(2, 2) = 0;
  s = stability_analysis(k, m, 1);
  EXPECT_GT(std::abs(s.static_mode(2)), 0.999 * s.static_mode.norm());
}

TEST(StabilityAnalysis, ModeKindFromThePivot) {
  // Points of a unit cube around its centroid.
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 8; ++i)
    pts.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  Vector6 slide;
  slide << 1, 0, -0.2, 0, 0, 0.01;
  EXPECT_FALSE(describe_mode(slide, pts).rotates);
  // Turning about the bottom edge y = -0.5, z = -0.5 (along x): the edge
  // stays put.
  Vector6 topple;
  const Eigen::Vector3d w(1, 0, 0), pivot(0, -0.5, -0.5);
  topple << -w.cross(pivot), w;
  const RigidMode mode = describe_mode(topple, pts);
  EXPECT_TRUE(mode.rotates);
  EXPECT_NEAR(mode.rotation.normalized().cross(Eigen::Vector3d::UnitX()).norm(), 0, 1e-12);
}

}  // namespace
}  // namespace rockface::mechanics
