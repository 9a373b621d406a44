#include "core/kinematics/sliding_mode.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/common/units.h"
#include "core/geometry/orientation.h"

namespace rockface::kinematics {
namespace {

Eigen::Vector3d n_deg(double dip, double dipdir) {
  return geometry::plane_normal_deg(dip, dipdir);
}

// Closed-form expressions evaluated in double precision: 1e-12 relative.
constexpr double kClosedForm = 1e-12;

TEST(SlidingMode, BlockOnAPlaneFollowsTanPhiOverTanPsi) {
  for (double psi : {10.0, 30.0, 55.0})
    for (double phi : {20.0, 35.0}) {
      const ContactPlane plane{0, n_deg(psi, 120), deg_to_rad(phi), 0};
      const SlidingMode m = sliding_mode(Eigen::Vector3d(0, 0, -1000), {plane}, 0);
      ASSERT_EQ(m.type, ModeType::Sliding);
      ASSERT_TRUE(m.fos);
      EXPECT_NEAR(*m.fos, std::tan(deg_to_rad(phi)) / std::tan(deg_to_rad(psi)), kClosedForm);
      // Sliding straight down the dip.
      const Eigen::Vector3d down = geometry::line_direction({deg_to_rad(120), deg_to_rad(psi)});
      EXPECT_NEAR((m.direction - down).norm(), 0, kClosedForm);
      EXPECT_FALSE(m.marginal);
    }
}

TEST(SlidingMode, CohesionAddsToResistance) {
  // W = 1000 N on a 30 degree plane, phi 30, c A = 200 N:
  // FoS = (W cos psi tan phi + cA) / (W sin psi).
  const double psi = deg_to_rad(30), phi = deg_to_rad(30);
  const ContactPlane plane{0, n_deg(30, 0), phi, 200};
  const SlidingMode m = sliding_mode(Eigen::Vector3d(0, 0, -1000), {plane}, 0);
  ASSERT_TRUE(m.fos);
  EXPECT_NEAR(*m.fos, (1000 * std::cos(psi) * std::tan(phi) + 200) / (1000 * std::sin(psi)),
              kClosedForm);
}

TEST(SlidingMode, SymmetricWedgeFollowsWedgeFactor) {
  // Two planes dipping 60 towards 135 and 225 form a symmetric wedge whose
  // line of intersection plunges psi_i towards 180. Resolving the weight
  // (Hoek & Bray): each face carries N = W cos(psi_i) / (2 sin(xi / 2)), xi
  // the wedge's opening angle, so FoS = k tan(phi) / tan(psi_i) with the
  // wedge factor k = 1 / sin(xi / 2).
  const Eigen::Vector3d n1 = n_deg(60, 135), n2 = n_deg(60, 225);
  const double phi = deg_to_rad(30);
  const SlidingMode m =
      sliding_mode(Eigen::Vector3d(0, 0, -1), {{0, n1, phi, 0}, {1, n2, phi, 0}}, 0);
  ASSERT_EQ(m.type, ModeType::Sliding);
  ASSERT_EQ(m.planes.size(), 2u);
  const Eigen::Vector3d line = n1.cross(n2).normalized();
  const double psi_i = std::asin(std::abs(line.z()));
  // The faces' outward normals are -n1, -n2; the opening angle between the
  // faces is pi minus the angle between their normals.
  const double xi = std::numbers::pi - std::acos(std::clamp(n1.dot(n2), -1.0, 1.0));
  const double expected = std::tan(phi) / (std::tan(psi_i) * std::sin(xi / 2));
  ASSERT_TRUE(m.fos);
  EXPECT_NEAR(*m.fos, expected, kClosedForm);
  EXPECT_NEAR(m.normal_forces[0], m.normal_forces[1], kClosedForm);  // symmetric
  EXPECT_NEAR(m.direction.z(), -std::sin(psi_i), kClosedForm);       // down the intersection
}

TEST(SlidingMode, ResultantInsidePyramidFalls) {
  // A block under a roof: joints with block-side normals pointing down and
  // inward; gravity points into the pyramid.
  const ContactPlane a{0, Eigen::Vector3d(0.5, 0, -1).normalized(), deg_to_rad(30), 0};
  const ContactPlane b{1, Eigen::Vector3d(-0.5, 0, -1).normalized(), deg_to_rad(30), 0};
  const SlidingMode m = sliding_mode(Eigen::Vector3d(0, 0, -9.81), {a, b}, 0);
  EXPECT_EQ(m.type, ModeType::Falling);
  ASSERT_TRUE(m.fos);
  EXPECT_EQ(*m.fos, 0.0);
}

TEST(SlidingMode, ResultantIntoRockIsStable) {
  // Resting on a horizontal floor: no sliding, FoS infinite.
  const SlidingMode m =
      sliding_mode(Eigen::Vector3d(0, 0, -1), {{0, Eigen::Vector3d::UnitZ(), 0.5, 0}}, 0);
  EXPECT_EQ(m.type, ModeType::None);
  ASSERT_TRUE(m.fos);
  EXPECT_TRUE(std::isinf(*m.fos));
}

TEST(SlidingMode, NoFrictionGivenNoFactorOfSafety) {
  const SlidingMode m =
      sliding_mode(Eigen::Vector3d(0, 0, -1), {{0, n_deg(40, 10), std::nullopt, 0}}, 0);
  EXPECT_EQ(m.type, ModeType::Sliding);
  EXPECT_FALSE(m.fos);
}

TEST(SlidingMode, ResultantAlongAPlaneIsMarginalButContinuous) {
  // r exactly in a vertical plane's face: falling with zero margin, FoS 0.
  const ContactPlane wall{0, Eigen::Vector3d::UnitX(), deg_to_rad(30), 0};
  const SlidingMode m = sliding_mode(Eigen::Vector3d(0, 0, -1), {wall}, deg_to_rad(1));
  EXPECT_TRUE(m.marginal);
  ASSERT_TRUE(m.fos);
  EXPECT_EQ(*m.fos, 0.0);
  // Tilted a hair into the wall: sliding on it with a tiny normal force, FoS ~ 0.
  const SlidingMode t = sliding_mode(Eigen::Vector3d(-1e-9, 0, -1), {wall}, deg_to_rad(1));
  EXPECT_TRUE(t.marginal);
  ASSERT_TRUE(t.fos);
  EXPECT_NEAR(*t.fos, 0.0, 1e-8);  // N/T = 1e-9 tan 30: continuous with the falling case
}

}  // namespace
}  // namespace rockface::kinematics
