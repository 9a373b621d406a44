// The design profile: circles, rectangles and horseshoes against their
// closed forms (perimeter, area, ray distances), the arc-length
// parametrisation, and every way a profile can be bad.
#include "core/tunnel/design_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"

namespace rockface::tunnel {
namespace {

constexpr double kPi = std::numbers::pi;
// Closed forms in doubles on metre-sized figures: a few ulps.
constexpr double kExact = 1e-12;

TEST(DesignProfile, CircleMatchesItsClosedForms) {
  const DesignProfile p = circle_profile(3.5, 1.0);
  ASSERT_TRUE(p.validate().ok) << p.validate().message;
  EXPECT_NEAR(p.perimeter(), 2 * kPi * 3.5, kExact);
  EXPECT_NEAR(p.area(), kPi * 3.5 * 3.5, 1e-11);
  EXPECT_NEAR((p.ray_centre() - Eigen::Vector2d(0, 1)).norm(), 0, kExact);
  for (double a = -3; a < 3.2; a += 0.37) {
    const ProfileHit h = p.ray_hit(a);
    EXPECT_NEAR(h.distance, 3.5, kExact) << a;
    EXPECT_NEAR((h.outward_normal - Eigen::Vector2d(std::cos(a), std::sin(a))).norm(), 0, 1e-12);
    // The hit's arc length leads back to the same point.
    EXPECT_NEAR((p.point_at_length(h.s) - h.point).norm(), 0, 1e-11) << a;
  }
  // s = 0 at the bottom, running counter-clockwise: a quarter round is the
  // right springline.
  EXPECT_NEAR((p.point_at_length(0) - Eigen::Vector2d(0, -2.5)).norm(), 0, kExact);
  EXPECT_NEAR((p.point_at_length(p.perimeter() / 4) - Eigen::Vector2d(3.5, 1)).norm(), 0, 1e-12);
  EXPECT_NEAR((p.outward_normal_at_length(p.perimeter() / 4) - Eigen::Vector2d(1, 0)).norm(), 0,
              1e-12);
}

TEST(DesignProfile, RectangleAndItsRays) {
  const DesignProfile p = rectangle_profile(6, 4, -1);
  ASSERT_TRUE(p.validate().ok) << p.validate().message;
  EXPECT_NEAR(p.perimeter(), 20, kExact);
  EXPECT_NEAR(p.area(), 24, kExact);
  EXPECT_NEAR(p.radius_toward(0), 3, kExact);
  EXPECT_NEAR(p.radius_toward(kPi / 2), 2, kExact);
  EXPECT_NEAR(p.radius_toward(std::atan2(2, 3)), std::hypot(3, 2), 1e-12);  // the corner
  const ProfileHit floor = p.ray_hit(-kPi / 2);
  EXPECT_NEAR((floor.outward_normal - Eigen::Vector2d(0, -1)).norm(), 0, kExact);
  EXPECT_NEAR(floor.s, 0, kExact);
}

TEST(DesignProfile, HorseshoeClosesAndHasTheRightDimensions) {
  // Crown radius 5 m at the springline v = 1.5 m, walls of radius 10 m, flat
  // invert at v = -2.5 m.
  const DesignProfile p = horseshoe_profile(5, 1.5, 10, -2.5);
  ASSERT_TRUE(p.validate().ok) << p.validate().message;
  ASSERT_EQ(p.segments().size(), 5u);
  EXPECT_NEAR(p.radius_toward(kPi / 2), 5, kExact);  // the crown from its centre
  EXPECT_NEAR(p.radius_toward(0), 5, kExact);        // the springline
  // The invert's half-width: r - R + R cos(asin(drop / R)).
  const double half = 5 - 10 + 10 * std::cos(std::asin(4.0 / 10));
  EXPECT_NEAR(p.segments()[0].to.x(), half, kExact);
  EXPECT_NEAR(p.radius_toward(-kPi / 2), 4, kExact);
  // Area: the crown's half disc, two wall sectors minus their triangles
  // about the far centres, and the trapezoid between: checked against the
  // polygon of 200,000 chords of the outline, which misses the sagittas of
  // its chords (1.5e-4 m chords on radii >= 5 m: 6e-10 m) times the
  // perimeter (~30 m): ~2e-8 m^2.
  double poly = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = p.point_at_length(p.perimeter() * k / n);
    const Eigen::Vector2d b = p.point_at_length(p.perimeter() * (k + 1) / n);
    poly += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(p.area(), poly / 2, 1e-7);
  // The walls meet the crown tangentially: the outward normal is continuous.
  const double s_spring = p.segments()[0].length() + p.segments()[1].length();
  EXPECT_NEAR(
      (p.outward_normal_at_length(s_spring - 1e-9) - p.outward_normal_at_length(s_spring + 1e-9))
          .norm(),
      0, 1e-8);
  EXPECT_THROW(horseshoe_profile(5, 1.5, 3, -2.5), InputError);    // walls smaller than the crown
  EXPECT_THROW(horseshoe_profile(5, 1.5, 5.5, -4.5), InputError);  // walls cross before the invert
}

TEST(DesignProfile, AClockwiseChainIsTurnedRoundKeepingItsStart) {
  const Eigen::Vector2d a(0, 0), b(-2, 0), c(-2, 2), d(2, 2), e(2, 0);
  const DesignProfile p({ProfileSegment::line(a, b), ProfileSegment::line(b, c),
                         ProfileSegment::line(c, d), ProfileSegment::line(d, e),
                         ProfileSegment::line(e, a)});
  ASSERT_TRUE(p.validate().ok) << p.validate().message;
  EXPECT_NEAR((p.point_at_length(0) - a).norm(), 0, kExact);
  EXPECT_NEAR((p.point_at_length(1) - Eigen::Vector2d(1, 0)).norm(), 0, kExact);  // now toward +u
  EXPECT_NEAR(p.area(), 8, kExact);
  EXPECT_NEAR((p.ray_centre() - Eigen::Vector2d(0, 1)).norm(), 0, 1e-9);  // the centroid
}

TEST(DesignProfile, ArcGivenByPolarAngles) {
  const ProfileSegment s = ProfileSegment::arc_polar({0, 0}, 2, -kPi / 2, kPi / 2);
  EXPECT_TRUE(s.ccw);
  EXPECT_NEAR(s.length(), 2 * kPi, kExact);
  EXPECT_NEAR((s.point_at(kPi) - Eigen::Vector2d(2, 0)).norm(), 0, kExact);
  // Clockwise from the bottom (270 deg) to the top (90 deg): by the left.
  const ProfileSegment back = ProfileSegment::arc_polar({0, 0}, 2, 3 * kPi / 2, kPi / 2);
  EXPECT_FALSE(back.ccw);
  EXPECT_NEAR((back.point_at(kPi) - Eigen::Vector2d(-2, 0)).norm(), 0, kExact);
}

TEST(DesignProfile, BadProfilesAreRefusedWithTheSegment) {
  // Not closed.
  const DesignProfile open({ProfileSegment::line({0, 0}, {1, 0}),
                            ProfileSegment::line({1, 0}, {1, 1}),
                            ProfileSegment::line({1, 1}, {0, 0.5})});
  ProfileCheck c = open.validate();
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("not closed"), std::string::npos) << c.message;
  ASSERT_TRUE(c.segment);
  // A bow tie (lobes of unequal area) crosses itself.
  const DesignProfile bow(
      {ProfileSegment::line({0, 0}, {4, 2}), ProfileSegment::line({4, 2}, {4, 0}),
       ProfileSegment::line({4, 0}, {0, 3}), ProfileSegment::line({0, 3}, {0, 0})});
  c = bow.validate();
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("crosses itself"), std::string::npos) << c.message;
  // An arc whose ends are not on one circle about its centre.
  const DesignProfile skew(
      {ProfileSegment::arc({0, -1}, {0, 1.5}, {0, 0}), ProfileSegment::line({0, 1.5}, {0, -1})});
  c = skew.validate();
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("one circle"), std::string::npos) << c.message;
  EXPECT_EQ(c.segment, std::optional<std::size_t>(0));
  // A ray centre outside, and one that does not see the whole outline (an
  // L-shaped profile seen from the far end of one leg).
  const std::vector<ProfileSegment> ell = {
      ProfileSegment::line({0, 0}, {4, 0}), ProfileSegment::line({4, 0}, {4, 1}),
      ProfileSegment::line({4, 1}, {1, 1}), ProfileSegment::line({1, 1}, {1, 4}),
      ProfileSegment::line({1, 4}, {0, 4}), ProfileSegment::line({0, 4}, {0, 0})};
  c = DesignProfile(ell, Eigen::Vector2d(5, 5)).validate();
  EXPECT_FALSE(c.ok);
  c = DesignProfile(ell, Eigen::Vector2d(3.5, 0.5)).validate();
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("star-shaped"), std::string::npos) << c.message;
  EXPECT_TRUE(DesignProfile(ell, Eigen::Vector2d(0.5, 0.5)).validate().ok);
  try {
    bow.require_valid("profile.json");
    FAIL() << "a crossing profile was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("profile.json.segments["), std::string::npos) << e.what();
  }
  EXPECT_FALSE(DesignProfile().validate().ok);
}

}  // namespace
}  // namespace rockface::tunnel
