// The design profile's hard cases (issue 40): a nearly straight arc (radius
// 1e7 to 1e9 m over a 6 m roof) encloses the rectangle's area plus its thin
// circular segment; segments of 0.1 mm (a CAD drawing's chamfer) are kept,
// and the wedges around such a profile are those of the sharp corner.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::tunnel {
namespace {

// A 6 m x 5 m rectangle (30 m^2) whose roof, from (3, 5) to (-3, 5), is an
// arc of radius R bulging up (centre below the floor).
DesignProfile flat_arc_roof(double R) {
  const double half = 3, top = 5;
  const Eigen::Vector2d a(0, 0), b(half, 0), c(half, top), d(-half, top), e(-half, 0);
  // The centre on the axis, sqrt(R^2 - half^2) below the roof's ends:
  // written as R^2 - half^2 = (R - half)(R + half) so that it is exact to
  // the last digit at R = 1e9.
  const Eigen::Vector2d centre(0, top - std::sqrt((R - half) * (R + half)));
  return DesignProfile({ProfileSegment::line(a, b), ProfileSegment::line(b, c),
                        ProfileSegment::arc(c, d, centre, true), ProfileSegment::line(d, e),
                        ProfileSegment::line(e, a)},
                       Eigen::Vector2d(0, 2.5), "flat arc roof");
}

TEST(WedgesDesignProfile, NearlyStraightArcEnclosesTheRectanglePlusItsSegment) {
  for (double R : {1e7, 1e8, 1e9}) {
    const DesignProfile p = flat_arc_roof(R);
    ASSERT_TRUE(p.validate().ok) << R << ": " << p.validate().message;
    // The circular segment over a chord of 6 m: R^2 (t - sin t) / 2 with
    // t = 2 asin(3 / R), by its series (t - sin t = t^3/6 - t^5/120 + ...,
    // the next term below 1e-40 relative here): 1.8e-6 m^2 at 1e7.
    const double t = 2 * std::asin(3 / R);
    const double segment = R * R * (std::pow(t, 3) / 6 - std::pow(t, 5) / 120) / 2;
    const double truth = 30 + segment;
    // Rounding: the straight parts' cross products, ~1e-15 relative of
    // 30 m^2; the segment's own term is tiny. 1e-12 relative leaves a
    // thousand times that.
    EXPECT_NEAR(p.area(), truth, 1e-12 * truth) << "radius " << R;
    // The perimeter: 16 m of straight sides and the arc, R t.
    EXPECT_NEAR(p.perimeter(), 16 + R * t, 1e-12 * 22) << "radius " << R;
  }
}

// The 6 x 5 rectangle with its right floor corner cut by a chamfer of
// length `cut` (legs cut / sqrt 2).
DesignProfile chamfered_rectangle(double cut) {
  const double leg = cut / std::sqrt(2.0);
  const Eigen::Vector2d a(0, 0), b1(3 - leg, 0), b2(3, leg), c(3, 5), d(-3, 5), e(-3, 0);
  return DesignProfile(
      {ProfileSegment::line(a, b1), ProfileSegment::line(b1, b2), ProfileSegment::line(b2, c),
       ProfileSegment::line(c, d), ProfileSegment::line(d, e), ProfileSegment::line(e, a)},
      Eigen::Vector2d(0, 2.5), "chamfered rectangle");
}

TEST(WedgesDesignProfile, TenthOfAMillimetreSegmentsAreKept) {
  for (double cut : {1e-4, 1e-5}) {
    const DesignProfile p = chamfered_rectangle(cut);
    const ProfileCheck check = p.validate();
    EXPECT_TRUE(check.ok) << cut << ": " << check.message;
    // The rectangle less the chamfer's triangle (legs cut / sqrt 2).
    EXPECT_NEAR(p.area(), 30 - cut * cut / 4, 1e-14 * 30) << cut;
  }
  // Below a micrometre a segment has no length (kProfileSegmentMinM).
  const ProfileCheck tiny = chamfered_rectangle(1e-7).validate();
  EXPECT_FALSE(tiny.ok);
  EXPECT_NE(tiny.message.find("has no length"), std::string::npos) << tiny.message;
}

TEST(WedgesDesignProfile, WedgesAroundAChamferAreThoseOfTheSharpCorner) {
  constexpr double kRad = 3.141592653589793 / 180;
  const std::vector<WedgeJointSet> sets{{"J1", geometry::plane_normal_deg(65, 20), 32 * kRad, 0},
                                        {"J2", geometry::plane_normal_deg(60, 145), 30 * kRad, 0},
                                        {"J3", geometry::plane_normal_deg(55, 260), 30 * kRad, 0}};
  const TunnelFrame frame = axis_frame(35 * kRad, 2 * kRad, Eigen::Vector3d::Zero(), "axis");
  const WedgeAnalysis sharp =
      analyse_wedges(rectangle_profile(6, 5, 0), frame, Eigen::Vector3d::Zero(), sets, {});
  const WedgeAnalysis cut =
      analyse_wedges(chamfered_rectangle(1e-4), frame, Eigen::Vector3d::Zero(), sets, {});
  ASSERT_FALSE(sharp.wedges.empty());
  ASSERT_EQ(cut.wedges.size(), sharp.wedges.size());
  for (std::size_t i = 0; i < sharp.wedges.size(); ++i) {
    EXPECT_EQ(cut.wedges[i].code, sharp.wedges[i].code);
    // The chamfer moves a point where the largest wedge's sector touches
    // the section by at most its 0.1 mm: the wedge's linear size (metres)
    // changes by under 1e-4 relative, its volume by under 3e-4.
    EXPECT_NEAR(cut.wedges[i].mass.volume, sharp.wedges[i].mass.volume,
                3e-4 * sharp.wedges[i].mass.volume)
        << sharp.wedges[i].code;
  }
}

}  // namespace
}  // namespace rockface::tunnel
