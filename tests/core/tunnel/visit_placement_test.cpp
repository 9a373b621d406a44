#include "core/tunnel/visit_placement.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/tunnel/face_front.h"
#include "core/tunnel/surface_reach.h"

namespace rockface::tunnel {
namespace {

using Eigen::Vector3d;

constexpr double kRadius = 3.0;  // the design circle's, and the excavated round's
constexpr double kRelief = 0.4;  // how far the face's centre bulges toward the cameras

Alignment straight_north(Drive drive = Drive::ascending) {
  return Alignment::from_elements({{0, {1000, 2000, 300}}, {100, {1000, 2100, 300}}}, {0},
                                  Vector3d(1000, 2000, 300), drive);
}

// A round excavated exactly to the design circle: the walls for 8 m behind
// the face, and the face a paraboloid that meets the walls at
// `face_chainage` and bulges kRelief toward the cameras at its centre. Rings
// every 0.25 m of radius and every 10 degrees, so that the rays face_front
// casts (the centre, and 30-degree directions at 0.25, 0.5 and 0.7 of the
// radius) meet the face at its vertices.
struct Round {
  std::vector<Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::uint8_t> not_rock;

  SurfaceInput input() const {
    SurfaceInput s;
    s.vertices = vertices;
    s.triangles = triangles;
    s.not_rock_vertex = not_rock;
    return s;
  }
  // A quad strip (two triangles), its vertices flagged `rock` or not.
  void add_quad(const std::array<Vector3d, 4>& q, bool rock) {
    const int base = static_cast<int>(vertices.size());
    for (const auto& v : q) {
      vertices.push_back(v);
      not_rock.push_back(rock ? 0 : 1);
    }
    triangles.push_back({base, base + 1, base + 2});
    triangles.push_back({base, base + 2, base + 3});
  }
};

Round excavated_round(const Alignment& alignment, double face_chainage) {
  const double sense = alignment.drive() == Drive::ascending ? 1.0 : -1.0;
  constexpr int kSectors = 36;
  constexpr int kRings = 12;  // kRadius / 0.25
  const auto face_at = [&](double r) {
    return face_chainage - sense * kRelief * (1 - r * r / (kRadius * kRadius));
  };
  const auto point = [&](double chainage, double r, int sector) {
    const double angle = 2 * std::numbers::pi * sector / kSectors;
    return alignment.frame_at(chainage).to_local(r * std::cos(angle), r * std::sin(angle));
  };
  Round round;
  for (int s = 0; s < kSectors; ++s) {
    for (int ring = 0; ring < kRings; ++ring) {
      const double r0 = kRadius * ring / kRings, r1 = kRadius * (ring + 1) / kRings;
      round.add_quad({point(face_at(r0), r0, s), point(face_at(r1), r1, s),
                      point(face_at(r1), r1, s + 1), point(face_at(r0), r0, s + 1)},
                     true);
    }
    for (int step = 0; step < 32; ++step) {  // walls every 0.25 m of chainage
      const double c0 = face_chainage - sense * 0.25 * (step + 1);
      const double c1 = face_chainage - sense * 0.25 * step;
      round.add_quad({point(c0, kRadius, s), point(c1, kRadius, s), point(c1, kRadius, s + 1),
                      point(c0, kRadius, s + 1)},
                     true);
    }
  }
  return round;
}

// The range pole standing 2 m in front of the face, 0.12 m wide, across the
// whole height of the round: it shadows the rays on the vertical through the
// axis (the centre, and the 90 and 270 degree directions at three radii).
// Off centre by 1 cm, so that no ray runs along the diagonal of its quad.
void add_pole(Round& round, const Alignment& alignment, double chainage, bool marked) {
  const TunnelFrame f = alignment.frame_at(chainage);
  round.add_quad({f.to_local(-0.05, -kRadius), f.to_local(0.07, -kRadius),
                  f.to_local(0.07, kRadius), f.to_local(-0.05, kRadius)},
                 !marked);
}

FrameRegistration by_ground_control() {
  FrameRegistration r;
  r.method = VisitPlacement::Method::ground_control;
  r.residuals = {{"P1", {0.003, -0.002, 0.001}}, {"P2", {-0.004, 0.001, 0.002}}};
  r.rms_m = 0.004;
  return r;
}

TEST(VisitPlacement, TheFaceStandsWhereTheMedianRayAlongTheAxisMeetsIt) {
  const Alignment alignment = straight_north();
  const Round round = excavated_round(alignment, 14.0);
  const VisitPlacement p = place_visit(alignment, circle_profile(kRadius), round.input(),
                                       by_ground_control(), "visit 7");
  // Of the 37 rays (1 at the centre: 13.6; 12 each at 0.25, 0.5 and 0.7 of
  // the radius: 13.625, 13.7, 13.796), the median is one at half the radius,
  // 14 - 0.4 (1 - 0.25) = 13.7. The rays meet the face at its vertices: only
  // rounding is left.
  EXPECT_NEAR(p.chainage, 13.7, 1e-9);
  // The face and walls within 0.3 m of it are symmetric about the axis and
  // its horizontal: the medians of offset and height are vertices on them.
  EXPECT_NEAR(p.offset_m, 0.0, 1e-9);
  ASSERT_TRUE(p.height_m);
  EXPECT_NEAR(*p.height_m, 0.0, 1e-9);
}

TEST(VisitPlacement, MonitoringTargetsPlaceTheVisitWithTheirResiduals) {
  const Alignment alignment = straight_north();
  const Round round = excavated_round(alignment, 14.0);
  const VisitPlacement p = place_visit(alignment, circle_profile(kRadius), round.input(),
                                       by_ground_control(), "visit 7");
  EXPECT_EQ(p.method, VisitPlacement::Method::ground_control);
  ASSERT_EQ(p.residuals.size(), 2u);
  EXPECT_EQ(p.residuals[1].label, "P2");
  ASSERT_TRUE(p.rms_m);
  EXPECT_DOUBLE_EQ(*p.rms_m, 0.004);
  EXPECT_FALSE(p.compass_azimuth_deg);
  EXPECT_EQ(p.note, "2 monitoring targets with survey coordinates");
}

TEST(VisitPlacement, ARangePoleAndCompassSayHowThePoleWasPlaced) {
  const Alignment alignment = straight_north();
  const Round round = excavated_round(alignment, 14.0);
  FrameRegistration compass;
  compass.compass_azimuth_deg = 91.5;
  compass.residuals = {{"lower target", {0.001, 0, 0}}};  // not reported for a compass line
  const VisitPlacement surveyed =
      place_visit(alignment, circle_profile(kRadius), round.input(), compass, "visit 3");
  EXPECT_EQ(surveyed.method, VisitPlacement::Method::chainage_compass);
  ASSERT_TRUE(surveyed.compass_azimuth_deg);
  EXPECT_DOUBLE_EQ(*surveyed.compass_azimuth_deg, 91.5);
  EXPECT_TRUE(surveyed.residuals.empty());
  EXPECT_FALSE(surveyed.rms_m);
  EXPECT_EQ(surveyed.note, "range pole at its surveyed position, north from the compass line");
  compass.typed = "chainage 12.00, offset 0.50 m (typed)";
  const VisitPlacement typed =
      place_visit(alignment, circle_profile(kRadius), round.input(), compass, "visit 3");
  EXPECT_EQ(typed.note,
            "range pole at chainage 12.00, offset 0.50 m (typed), north from the compass line");
  EXPECT_EQ(typed.chainage, surveyed.chainage);
}

// Issue 42: a 3D image the range pole scaled and levelled without a compass
// line has the camera's heading for north; placed by chainage it would be
// compared with the design profile at that random turn. Refused by name.
TEST(VisitPlacement, AChainagePlacementWithoutNorthIsRefused) {
  const Alignment alignment = straight_north();
  const Round round = excavated_round(alignment, 14.0);
  FrameRegistration pole_only;
  pole_only.north_known = false;
  pole_only.typed = "chainage 12.00, offset 0.50 m (typed)";
  try {
    place_visit(alignment, circle_profile(kRadius), round.input(), pole_only, "visit 4");
    FAIL() << "placed without north";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("visit 4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no north"), std::string::npos) << e.what();
  }
  // Monitoring targets bring their own north: the same flag does not apply.
  FrameRegistration targets = by_ground_control();
  targets.north_known = false;
  EXPECT_NO_THROW(
      place_visit(alignment, circle_profile(kRadius), round.input(), targets, "visit 4"));
}

TEST(VisitPlacement, ADescendingDriveFindsTheFaceAtItsLowerChainage) {
  const Alignment alignment = straight_north(Drive::descending);
  const Round round = excavated_round(alignment, 50.0);
  const VisitPlacement p = place_visit(alignment, circle_profile(kRadius), round.input(),
                                       by_ground_control(), "visit 4");
  // The face bulges toward higher chainage, the median ray meets it at
  // 50 + 0.4 (1 - 0.25); at its vertices, as above.
  EXPECT_NEAR(p.chainage, 50.3, 1e-9);
}

TEST(VisitPlacement, TheRangePoleInFrontOfTheFaceIsNotTheFace) {
  const Alignment alignment = straight_north();
  const DesignProfile circle = circle_profile(kRadius);
  Round marked = excavated_round(alignment, 14.0);
  Round unmarked = marked;
  add_pole(marked, alignment, 12.0, true);
  add_pole(unmarked, alignment, 12.0, false);
  // Read as rock, the pole is where the face reaches farthest back.
  const auto through_pole = face_front(alignment, circle, unmarked.input(), 6.5);
  ASSERT_TRUE(through_pole);
  EXPECT_NEAR(through_pole->nearest_chainage, 12.0, 1e-9);  // the pole's plane, up to rounding
  EXPECT_EQ(through_pole->hits, 37);
  // Marked, the 7 rays on the vertical through the axis count for nothing,
  // and the face's centre ring is its nearest part again.
  const auto front = face_front(alignment, circle, marked.input(), 6.5);
  ASSERT_TRUE(front);
  EXPECT_EQ(front->rays, 37);
  EXPECT_EQ(front->hits, 30);
  EXPECT_NEAR(front->nearest_chainage, 14 - kRelief * (1 - 0.25 * 0.25), 1e-9);
  // Its four vertices are not among the rock's places.
  EXPECT_EQ(rock_places(alignment, marked.input()).size(), marked.vertices.size() - 4);
}

TEST(VisitPlacement, TheSurfaceReachesFromTheRearOfTheWallsToTheFace) {
  const Alignment alignment = straight_north();
  const Round round = excavated_round(alignment, 14.0);
  const auto reach = surface_reach(alignment, rock_places(alignment, round.input()));
  ASSERT_TRUE(reach);
  // The walls run from 6 to 14 and hold most vertices; the face's vertices
  // lie between 13.6 and 14: the 2nd and 99th percentiles lie inside.
  EXPECT_GE(reach->rear, 6.0 - 1e-9);
  EXPECT_LT(reach->rear, 7.0);
  EXPECT_GT(reach->front, 13.6);
  EXPECT_LE(reach->front, 14.0 + 1e-9);
}

TEST(VisitPlacement, ASurfaceWithoutRockIsRefusedNamingTheVisit) {
  const Alignment alignment = straight_north();
  Round round = excavated_round(alignment, 14.0);
  round.not_rock.assign(round.vertices.size(), 1);
  try {
    place_visit(alignment, circle_profile(kRadius), round.input(), by_ground_control(), "visit 9");
    FAIL() << "placed a surface with no rock";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("visit 9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no rock"), std::string::npos) << e.what();
  }
}

TEST(VisitPlacement, TheTypedPoleLiesAtItsChainageOffsetAndHeight) {
  const Alignment alignment = straight_north();
  // North-going axis through the datum: right = east (+x), up = +z.
  const Vector3d pole = typed_pole_position(alignment, 12.0, 0.5, -1.2);
  EXPECT_NEAR(pole.x(), 0.5, 1e-9);
  EXPECT_NEAR(pole.y(), 12.0, 1e-9);
  EXPECT_NEAR(pole.z(), -1.2, 1e-9);
  EXPECT_THROW(typed_pole_position(alignment, 150.0, 0, 0), InputError);
}

// Issue 41: a typed chainage of 1e308 was refused with all 309 of its digits.
TEST(VisitPlacement, AChainageBeyondAnyAlignmentIsSaidInSixDigits) {
  const Alignment alignment = straight_north();
  auto said = [&](double chainage) {
    try {
      typed_pole_position(alignment, chainage, 0, 0);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string range = " is off the alignment (" +
                            format_fixed(alignment.first_chainage(), 2) + " to " +
                            format_fixed(alignment.last_chainage(), 2) + ")";
  EXPECT_EQ(said(1e308), "tunnel.placement.chainage: 1e+308" + range);
  EXPECT_EQ(said(-1.5e300), "tunnel.placement.chainage: -1.5e+300" + range);
  EXPECT_EQ(said(150), "tunnel.placement.chainage: 150.00" + range);
}

// Issue 41: an offset of 130 m (or 1e308) from the axis was taken without a
// word; the pole stands in the excavation, at most 50 m from the axis.
TEST(VisitPlacement, ATypedPoleFartherThanAnyTunnelsHalfWidthIsRefusedByName) {
  const Alignment alignment = straight_north();
  auto said = [&](double offset, double height) {
    try {
      typed_pole_position(alignment, 12.0, offset, height);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(said(130, 0),
            "tunnel.placement.offset: 130 m from the axis is more than any tunnel's half-width (at "
            "most 50 m): a typo, or the pole outside the excavation?");
  EXPECT_EQ(said(0, -1e308).substr(0, 41), "tunnel.placement.height: -1e+308 m from t");
  EXPECT_EQ(said(-50, 50), "accepted");
}

}  // namespace
}  // namespace rockface::tunnel
