#pragma once
// A visit's findings relative to the tunnel: where a measured plane, a
// block or the face lies (chainage, offset, height) and how a plane strikes
// against the drive (Bieniawski's classes), and the shift that places a
// visit by the chainage the geologist typed when no survey target is in view.
#include <span>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"
#include "core/tunnel/strike_vs_drive.h"

namespace rockface::tunnel {

struct PlaneInTunnel {
  AlignmentPlace place;  // of the plane's point
  StrikeVsDrive strike;  // against the drive's trend at that chainage
};

// A plane through `point` (datum-relative) with normal `normal` (either sense).
PlaneInTunnel plane_in_tunnel(const Alignment& alignment, const Eigen::Vector3d& point,
                              const Eigen::Vector3d& normal, double uncertainty_deg = 5.0);

// Where a visit's face is: the chainage of the face (the 98th percentile of
// the surface points' chainages in the drive direction: the furthest rock,
// robust to a few stray points ahead), the offset and height of the points'
// centroid in the section there, and the chainage range the points cover
// (the walls and roof seen behind the face). Throws InputError("points")
// when empty.
struct FacePlace {
  double face_chainage = 0;
  double offset = 0, height = 0;  // of the centroid
  double chainage_min = 0, chainage_max = 0;
  bool inside = true;  // every point within the alignment's chainage range
};
FacePlace face_place(const Alignment& alignment, std::span<const Eigen::Vector3d> points);

// Placing a visit by typed chainage (+ the compass line that already
// oriented its 3D image north and level): the shift to add to every point
// of the face frame so that `face_point` lands at `chainage`, `offset` right
// of the axis and `height` above it.
Eigen::Vector3d shift_to_chainage(const Alignment& alignment, const Eigen::Vector3d& face_point,
                                  double chainage, double offset = 0, double height = 0);

}  // namespace rockface::tunnel
