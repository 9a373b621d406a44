// A visit's findings relative to the tunnel: a plane's place and its class
// against the drive, the face's chainage, and placing by typed chainage.
#include "core/tunnel/tunnel_relative.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/error.h"
#include "core/geometry/orientation.h"

namespace rockface::tunnel {
namespace {

// Closed forms on ~10 m coordinates (datum-relative): a few ulps.
constexpr double kExactM = 1e-9;

Alignment north(Drive drive) {
  const Eigen::Vector3d datum(2690000, 1250000, 500);
  return Alignment::from_elements({{100, datum}, {130, datum + Eigen::Vector3d(0, 30, 0)}}, {0},
                                  datum, drive);
}

TEST(TunnelRelative, APlaneIsPlacedAndClassedAgainstTheDrive) {
  const Alignment al = north(Drive::ascending);
  const Eigen::Vector3d p = al.frame_at(105).to_local(2, 1);
  const PlaneInTunnel r = plane_in_tunnel(al, p, geometry::plane_normal_deg(60, 10));
  EXPECT_NEAR(r.place.chainage, 105, kExactM);
  EXPECT_NEAR(r.place.offset, 2, kExactM);
  EXPECT_EQ(r.strike.cls, DriveClass::very_favourable);
  // Driving the other way, the same joints dip against the drive.
  EXPECT_EQ(
      plane_in_tunnel(north(Drive::descending), p, geometry::plane_normal_deg(60, 10)).strike.cls,
      DriveClass::fair);
}

// Walls from chainage 107 to 120 (every 0.1 m round a 3 m circle) and the
// face at 120 (a grid across the section): the face is the furthest rock.
std::vector<Eigen::Vector3d> heading(const Alignment& al, double from, double face) {
  std::vector<Eigen::Vector3d> pts;
  const double step = face > from ? 0.1 : -0.1;
  for (double c = from; step * (face - c) > -1e-9; c += step)
    for (int i = 0; i < 36; ++i)
      pts.push_back(al.frame_at(c).to_local(3 * std::cos(i * std::numbers::pi / 18),
                                            3 * std::sin(i * std::numbers::pi / 18)));
  for (int u = -20; u <= 20; ++u)
    for (int v = -20; v <= 20; ++v)
      if (u * u + v * v < 400) pts.push_back(al.frame_at(face).to_local(0.14 * u + 0.5, 0.14 * v));
  return pts;
}

TEST(TunnelRelative, TheFaceIsTheFurthestRockInTheDriveDirection) {
  const Alignment up = north(Drive::ascending);
  const auto pts = heading(up, 107, 120);
  const FacePlace f = face_place(up, pts);
  EXPECT_NEAR(f.face_chainage, 120, kExactM);
  EXPECT_NEAR(f.chainage_min, 107, kExactM);
  EXPECT_NEAR(f.chainage_max, 120, kExactM);
  EXPECT_TRUE(f.inside);
  // The face's grid is centred 0.5 m right and the walls are symmetric
  // about the axis: the centroid lies 0.5 m x (face points / all points)
  // right (rounding of the 36 cosines: ~1e-15 m).
  int face_points = 0;
  for (int u = -20; u <= 20; ++u)
    for (int v = -20; v <= 20; ++v) face_points += u * u + v * v < 400;
  EXPECT_NEAR(f.offset, 0.5 * face_points / static_cast<double>(pts.size()), 1e-9);
  // Driving toward falling chainage: the face is at the low end.
  const Alignment down = north(Drive::descending);
  const FacePlace g = face_place(down, heading(down, 125, 110));
  EXPECT_NEAR(g.face_chainage, 110, kExactM);
  EXPECT_THROW(face_place(up, {}), InputError);
}

TEST(TunnelRelative, ATypedChainagePlacesTheFace) {
  const Alignment al = north(Drive::ascending);
  const Eigen::Vector3d face_point(0.3, -0.2, 1.7);  // the face frame's point to place
  const Eigen::Vector3d shift = shift_to_chainage(al, face_point, 117.25, -0.4, 0.2);
  const AlignmentPlace p = al.place(face_point + shift);
  EXPECT_NEAR(p.chainage, 117.25, kExactM);
  EXPECT_NEAR(p.offset, -0.4, kExactM);
  EXPECT_NEAR(p.height, 0.2, kExactM);
  EXPECT_THROW(shift_to_chainage(al, face_point, 140), InputError);
}

}  // namespace
}  // namespace rockface::tunnel
