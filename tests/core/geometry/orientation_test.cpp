#include "core/geometry/orientation.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "core/common/units.h"

namespace rockface::geometry {
namespace {

Eigen::Vector3d normal_deg(double dip, double dipdir) {
  return plane_normal_deg(dip, dipdir);
}

// Closed-form trigonometry in double precision: components agree to a few ulp
// of 1, so 1e-12 leaves room for the sin/cos library error and nothing more.
constexpr double kTrig = 1e-12;

TEST(Orientation, NormalFollowsDesignFormula) {
  const Eigen::Vector3d n = normal_deg(30, 90);
  EXPECT_NEAR(n.x(), 0.5, kTrig);
  EXPECT_NEAR(n.y(), 0.0, kTrig);
  EXPECT_NEAR(n.z(), std::sqrt(3.0) / 2, kTrig);
  // A vertical plane's normal points to its dip direction.
  const Eigen::Vector3d v = normal_deg(90, 180);
  EXPECT_NEAR(v.y(), -1.0, kTrig);
  EXPECT_NEAR(v.z(), 0.0, kTrig);
}

// plane_normal_deg is the conversion every caller used to write by hand, to
// the bit: any difference, even of one ulp or of the sign of a zero, could
// move a verdict's margin in its last digit.
TEST(Orientation, NormalFromDegreesIsBitEqualToNormalFromRadians) {
  for (double dip : {0.0, 1e-9, 0.5, 20.0, 30.0, 45.0, 60.0, 89.5, 90.0})
    for (double dipdir = 0; dipdir <= 360; dipdir += 7.5) {
      const Eigen::Vector3d from_deg = plane_normal_deg(dip, dipdir);
      const Eigen::Vector3d from_rad = plane_normal({deg_to_rad(dip), deg_to_rad(dipdir)});
      for (int i = 0; i < 3; ++i)
        EXPECT_EQ(std::bit_cast<std::uint64_t>(from_deg[i]),
                  std::bit_cast<std::uint64_t>(from_rad[i]))
            << "dip " << dip << ", dip direction " << dipdir << ", component " << i;
    }
}

TEST(Orientation, VerticalPlaneNormalFromDegreesPointsToItsDipDirection) {
  for (double dipdir : {0.0, 30.0, 90.0, 135.0, 180.0, 270.0, 330.0, 360.0}) {
    const Eigen::Vector3d n = plane_normal_deg(90, dipdir);
    const Eigen::Vector3d toward(std::sin(deg_to_rad(dipdir)), std::cos(deg_to_rad(dipdir)), 0);
    EXPECT_NEAR(n.z(), 0.0, kTrig) << dipdir;
    EXPECT_NEAR(n.dot(toward), 1.0, kTrig) << dipdir;
  }
}

TEST(Orientation, RoundTripsOverTheWholeRange) {
  for (double dip = 0.5; dip < 90; dip += 7.3)
    for (double dd = 0; dd < 360; dd += 11.1) {
      const PlaneOrientation o = plane_orientation(normal_deg(dip, dd));
      EXPECT_NEAR(rad_to_deg(o.dip), dip, 1e-9);
      EXPECT_NEAR(rad_to_deg(o.dipdir), dd, 1e-9);
    }
}

TEST(Orientation, DipDirection360IsZero) {
  const Eigen::Vector3d a = normal_deg(45, 0), b = normal_deg(45, 360);
  EXPECT_LT((a - b).norm(), kTrig);
  EXPECT_DOUBLE_EQ(wrap_azimuth(deg_to_rad(360)), 0.0);
  EXPECT_GE(wrap_azimuth(-1e-18), 0.0);
  EXPECT_LT(wrap_azimuth(-1e-18), 2 * kPi);
  // A normal that points a hair west of north comes back near 360, never as 360.
  const PlaneOrientation o = plane_orientation(normal_deg(60, 359.9999999));
  EXPECT_LT(o.dipdir, 2 * kPi);
}

TEST(Orientation, HorizontalAndVerticalPlanes) {
  const PlaneOrientation h = plane_orientation(Eigen::Vector3d(0, 0, -2));
  EXPECT_EQ(h.dip, 0.0);
  EXPECT_EQ(h.dipdir, 0.0);
  const PlaneOrientation v = plane_orientation(Eigen::Vector3d(-1, 0, 0));
  EXPECT_NEAR(rad_to_deg(v.dip), 90.0, kTrig);
  EXPECT_NEAR(rad_to_deg(v.dipdir), 270.0, 1e-9);
}

TEST(Orientation, PublishedCrossProduct) {
  // Planes 20/280 and 60/150: n1 x n2 = (0.7345, 0.5753, 0.2269) (published to 4 decimals).
  const Eigen::Vector3d c = normal_deg(20, 280).cross(normal_deg(60, 150));
  EXPECT_NEAR(c.x(), 0.7345, 5e-5);
  EXPECT_NEAR(c.y(), 0.5753, 5e-5);
  EXPECT_NEAR(c.z(), 0.2269, 5e-5);
}

TEST(Orientation, TrendPlungeRoundTrip) {
  for (double p = -85; p <= 90; p += 17)
    for (double t = 0; t < 360; t += 29) {
      const LineOrientation o = line_orientation(line_direction({deg_to_rad(t), deg_to_rad(p)}));
      EXPECT_NEAR(rad_to_deg(o.plunge), p, 1e-9);
      if (std::abs(p) < 90) {
        EXPECT_NEAR(rad_to_deg(o.trend), t, 1e-9);
      }
    }
  // Plunge is positive downward.
  EXPECT_LT(line_direction({0, deg_to_rad(30)}).z(), 0);
}

}  // namespace
}  // namespace rockface::geometry
