// The alignment against closed forms: a straight line and a circular arc
// (place() of points built at a known chainage, offset and height), the
// drive direction, survey coordinates of 10^6 m, points on the axis and at
// the ends, and every refusal of a bad table.
#include "core/tunnel/alignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/common/error.h"

namespace rockface::tunnel {
namespace {

constexpr double kPi = std::numbers::pi;

// Closed-form answers computed in doubles from coordinates of ~100 m: a few
// ulps of 100 m, far below 1e-9 m.
constexpr double kExactM = 1e-9;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// A straight element heading (0.6, 0.8) (azimuth 36.87 deg), 100 m, rising 2 m.
Alignment straight(const Eigen::Vector3d& origin, Drive drive = Drive::ascending) {
  return Alignment::from_elements({{1000, origin}, {1100, origin + Eigen::Vector3d(60, 80, 2)}},
                                  {0}, origin, drive);
}

TEST(Alignment, StraightLinePlacesPointsAtTheirChainageOffsetAndHeight) {
  const Eigen::Vector3d origin(0, 0, 0);
  const Alignment al = straight(origin);
  const TunnelFrame f = al.frame_at(1040);
  // Right of a drive heading (0.6, 0.8) is (0.8, -0.6), horizontal.
  EXPECT_NEAR(f.right.x(), 0.8, kExactM);
  EXPECT_NEAR(f.right.y(), -0.6, kExactM);
  EXPECT_NEAR(f.right.z(), 0, kExactM);
  EXPECT_NEAR(f.along.dot(f.right), 0, kExactM);
  EXPECT_NEAR(f.along.dot(f.up), 0, kExactM);
  EXPECT_GT(f.up.z(), 0.99);
  EXPECT_NEAR(f.origin.z(), 0.8, kExactM);  // 40 % of the 2 m rise
  const Eigen::Vector3d p = f.to_local(3.0, 1.5);
  const AlignmentPlace place = al.place(p);
  EXPECT_NEAR(place.chainage, 1040, kExactM);
  EXPECT_NEAR(place.offset, 3.0, kExactM);
  EXPECT_NEAR(place.height, 1.5, kExactM);
  EXPECT_TRUE(place.inside());
  EXPECT_NEAR(place.distance(), std::hypot(3.0, 1.5), kExactM);
}

TEST(Alignment, DescendingDriveLooksTheOtherWay) {
  const Alignment up = straight(Eigen::Vector3d::Zero(), Drive::ascending);
  const Alignment down = straight(Eigen::Vector3d::Zero(), Drive::descending);
  EXPECT_NEAR((up.tangent_at(1050) + down.tangent_at(1050)).norm(), 0, kExactM);
  const Eigen::Vector3d p = up.frame_at(1050).to_local(2.0, 1.0);
  const AlignmentPlace a = up.place(p), b = down.place(p);
  EXPECT_NEAR(a.chainage, b.chainage, kExactM);
  EXPECT_NEAR(a.offset, -b.offset, kExactM);  // right of one is left of the other
  EXPECT_NEAR(a.height, b.height, kExactM);
  // Trend of the descending drive: the azimuth of (-0.6, -0.8).
  EXPECT_NEAR(down.drive_trend_at(1050), std::atan2(-0.6, -0.8) + 2 * kPi, 1e-12);
}

TEST(Alignment, RightHandArcPlacesPointsOnConcentricCircles) {
  // Heading north from (0, 0), turning right (clockwise) on radius 200 m:
  // the centre is at (200, 0); 100 m of arc sweep 0.5 rad.
  const double R = 200, sweep = 0.5;
  const Eigen::Vector2d c(R, 0);
  const Eigen::Vector3d B(c.x() + R * std::cos(kPi - sweep), R * std::sin(kPi - sweep), 0);
  const Alignment al = Alignment::from_elements({{0, {0, 0, 0}}, {100, B}}, {R}, {0, 0, 0});
  for (double ch : {0.0, 30.0, 77.7, 100.0}) {
    const double theta = kPi - ch / R;
    const Eigen::Vector3d axis(c.x() + R * std::cos(theta), R * std::sin(theta), 0);
    EXPECT_NEAR((al.point_at(ch) - axis).norm(), 0, kExactM) << ch;
    // A point 2 m to the left (outside the curve: radius 202) and 0.5 m up.
    const Eigen::Vector3d p(c.x() + (R + 2) * std::cos(theta), (R + 2) * std::sin(theta), 0.5);
    const AlignmentPlace place = al.place(p);
    EXPECT_NEAR(place.chainage, ch, kExactM) << ch;
    EXPECT_NEAR(place.offset, -2, kExactM) << ch;
    EXPECT_NEAR(place.height, 0.5, kExactM) << ch;
  }
  // Tangent at the start is north; at the end turned right by 0.5 rad.
  EXPECT_NEAR((al.tangent_at(0) - Eigen::Vector3d(0, 1, 0)).norm(), 0, kExactM);
  EXPECT_NEAR(al.drive_trend_at(100), sweep, 1e-12);
}

TEST(Alignment, GradedArcRoundTripsThroughTheFrame) {
  // A straight, then a left-hand arc joining it tangentially, both at a 1 %
  // grade (at a change of grade the cross-sections of the two elements
  // overlap above the axis and leave a wedge below it; see alignment.h).
  const double R = 300, sweep = 0.5;
  const Eigen::Vector2d c(-R, 100);  // left of a northward heading
  const Eigen::Vector3d B(c.x() + R * std::cos(sweep), c.y() + R * std::sin(sweep), 2.5);
  const Alignment al = Alignment::from_elements(
      {{0, {0, 0, 0}}, {100, {0, 100, 1}}, {100 + R * sweep, B}}, {0, -R}, {0, 0, 0});
  for (double ch : {5.0, 99.999, 100.0, 120.0, 200.0, 249.0}) {
    const TunnelFrame f = al.frame_at(ch);
    for (const Eigen::Vector2d& uv : {Eigen::Vector2d(4, 3), Eigen::Vector2d(-5, -1)}) {
      const AlignmentPlace place = al.place(f.to_local(uv.x(), uv.y()));
      // Newton on the graded arc stops at kFootChainageM = 1e-9 m of
      // chainage; offsets then err by less than that times the ~1 %
      // grade, well inside 1e-8 m.
      EXPECT_NEAR(place.chainage, ch, 1e-8) << ch;
      EXPECT_NEAR(place.offset, uv.x(), 1e-8) << ch;
      EXPECT_NEAR(place.height, uv.y(), 1e-8) << ch;
    }
  }
}

TEST(Alignment, SurveyCoordinatesOfMillionsOfMetresLoseNoPrecision) {
  // Swiss LV95-like coordinates; the datum is the project's site origin.
  const Eigen::Vector3d datum(2690000.0, 1250000.0, 600.0);
  const Eigen::Vector3d s0 = datum + Eigen::Vector3d(12.345, 67.891, 1.5);
  const Alignment al =
      Alignment::from_elements({{1000, s0}, {1100, s0 + Eigen::Vector3d(60, 80, 2)}}, {0}, datum);
  const Eigen::Vector3d survey = al.survey_point_at(1040) + 3.0 * al.frame_at(1040).right;
  const AlignmentPlace place = al.place_survey(survey);
  // Survey coordinates of 2.7e6 m carry ~5e-10 m of rounding; datum-relative
  // arithmetic adds nothing of that order.
  EXPECT_NEAR(place.chainage, 1040, 2e-9);
  EXPECT_NEAR(place.offset, 3.0, 2e-9);
  EXPECT_NEAR(place.height, 0, 2e-9);
}

TEST(Alignment, PointsOnTheAxisAndAtTheEnds) {
  const Alignment al = straight(Eigen::Vector3d::Zero());
  const AlignmentPlace on = al.place(al.point_at(1033.25));
  EXPECT_NEAR(on.chainage, 1033.25, kExactM);
  EXPECT_NEAR(on.offset, 0, kExactM);
  EXPECT_NEAR(on.height, 0, kExactM);
  const AlignmentPlace start = al.place(al.point_at(1000));
  EXPECT_NEAR(start.chainage, 1000, kExactM);
  EXPECT_TRUE(start.inside());
  const AlignmentPlace end = al.place(al.point_at(1100) + al.frame_at(1100).right);
  EXPECT_NEAR(end.chainage, 1100, kExactM);
  EXPECT_TRUE(end.inside());
  EXPECT_NEAR(end.offset, 1, kExactM);
  // 5 m beyond the end: flagged with its distance, not clamped.
  const Eigen::Vector3d beyond = al.point_at(1100) + 5 * al.tangent_at(1100);
  const AlignmentPlace out = al.place(beyond);
  EXPECT_FALSE(out.inside());
  // 5 m along the graded tangent is 5 / sqrt(1 + 0.02^2) m of chainage.
  EXPECT_NEAR(out.beyond_range, 5 / std::sqrt(1 + 0.02 * 0.02), 1e-9);
  EXPECT_NEAR(out.chainage, 1100 + out.beyond_range, kExactM);
  const AlignmentPlace before = al.place(al.point_at(1000) - 2 * al.tangent_at(1000));
  EXPECT_FALSE(before.inside());
  EXPECT_LT(before.chainage, 1000);
  EXPECT_FALSE(al.contains(1100.001));
  EXPECT_TRUE(al.contains(1100));
}

TEST(Alignment, PolylineCornerWedgeTakesTheCornerChainage) {
  // Dense polyline: east 10 m, then north 10 m. A point outside the corner
  // (south-east of it) lies in no cross-section: it gets the corner's
  // chainage.
  const Alignment al =
      Alignment::from_polyline({{0, {0, 0, 0}}, {10, {10, 0, 0}}, {20, {10, 10, 0}}}, {0, 0, 0});
  EXPECT_TRUE(al.is_polyline());
  const AlignmentPlace p = al.place({12, -2, 0});
  EXPECT_NEAR(p.chainage, 10, kExactM);
  EXPECT_TRUE(p.inside());
  const AlignmentPlace q = al.place({9, 4, 1});  // inside the bend, on the second leg
  EXPECT_NEAR(q.chainage, 14, kExactM);
  EXPECT_NEAR(q.offset, -1, kExactM);  // heading north, x = 9 is 1 m left of the axis
  EXPECT_NEAR(q.height, 1, kExactM);
}

TEST(Alignment, BadTablesAreRefusedNamingTheStation) {
  const Eigen::Vector3d z = Eigen::Vector3d::Zero();
  EXPECT_NE(message_of([&] {
              Alignment::from_elements({{0, z}}, {}, z);
            }).find("at least two"),
            std::string::npos);
  // Zero-length element: two chainages, one point.
  const std::string zero = message_of([&] { Alignment::from_elements({{0, z}, {10, z}}, {0}, z); });
  EXPECT_NE(zero.find("zero-length element"), std::string::npos) << zero;
  EXPECT_NE(zero.find("stations[1]"), std::string::npos) << zero;
  // A radius below half the chord (chord 100 m, radius 40 m).
  const std::string radius = message_of([&] {
    Alignment::from_elements({{0, z}, {100, {0, 100, 0}}}, {40}, z);
  });
  EXPECT_NE(radius.find("smaller than half the chord"), std::string::npos) << radius;
  // Not ordered by chainage, and a duplicate.
  const std::string order = message_of([&] {
    Alignment::from_polyline({{0, z}, {20, {20, 0, 0}}, {10, {10, 0, 0}}}, z);
  });
  EXPECT_NE(order.find("ascending chainage"), std::string::npos) << order;
  EXPECT_NE(order.find("stations[2]"), std::string::npos) << order;
  const std::string dup = message_of([&] {
    Alignment::from_polyline({{0, z}, {10, {10, 0, 0}}, {10, {20, 0, 0}}}, z);
  });
  EXPECT_NE(dup.find("duplicate chainage"), std::string::npos) << dup;
  // The chainage says 100 m, the line is 90 m long.
  const std::string mismatch = message_of([&] {
    Alignment::from_elements({{0, z}, {100, {90, 0, 0}}}, {0}, z);
  });
  EXPECT_NE(mismatch.find("90 m long"), std::string::npos) << mismatch;
  // Non-finite values.
  const std::string nan = message_of([&] {
    Alignment::from_elements({{0, z}, {std::nan(""), {10, 0, 0}}}, {0}, z);
  });
  EXPECT_NE(nan.find("stations[1].chainage"), std::string::npos) << nan;
  EXPECT_NE(message_of([&] { drive_of("forward", "tunnel.drive"); }).find("tunnel.drive"),
            std::string::npos);
}

// Issue 41: +-1e308 in a table became null origins and a face "at offset
// 1000... (300 digits)"; coordinates are refused beyond the range of a
// survey, naming the station.
TEST(Alignment, CoordinatesBeyondAnySurveyAreRefusedByStation) {
  const Eigen::Vector3d d(0, 0, 0);
  EXPECT_EQ(message_of([&] {
              Alignment::from_elements({{0, d}, {100, Eigen::Vector3d(0, 1e308, 0)}}, {0}, d);
            }),
            "stations[1] (chainage 100): easting, northing and elevation must be survey "
            "coordinates (easting and northing within +-1e+08 m, elevation within +-100000 m)");
  EXPECT_EQ(message_of([&] {
              Alignment::from_elements({{-1e308, d}, {100, Eigen::Vector3d(0, 100, 0)}}, {0}, d);
            }),
            "stations[0].chainage: -1e+308 is outside +-1e+08 m");
  EXPECT_EQ(message_of([&] {
              Alignment::from_polyline({{0, d}, {100, Eigen::Vector3d(0, 100, 0)}},
                                       Eigen::Vector3d(0, 0, -1e308));
            }),
            "datum: must be survey coordinates (easting and northing within +-1e+08 m, "
            "elevation within +-100000 m)");
}

}  // namespace
}  // namespace rockface::tunnel
