#pragma once
// Orientation of planes (dip / dip direction) and lines (trend / plunge) and
// their unit vectors, in the project frame x = East, y = North, z = Up.
// Angles in radians here; degrees are converted at the program's boundary.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rockface::geometry {

struct PlaneOrientation {
  double dip = 0;      // [0, pi/2]
  double dipdir = 0;   // [0, 2 pi)
};

struct LineOrientation {
  double trend = 0;    // [0, 2 pi), azimuth of the horizontal projection
  double plunge = 0;   // [-pi/2, pi/2], positive downward
};

// Wraps an azimuth into [0, 2 pi): 360 degrees and 0 are the same direction.
double wrap_azimuth(double azimuth);

// Upward unit normal n = (sin a sin b, sin a cos b, cos a). A vertical plane's
// normal points to its dip direction.
Eigen::Vector3d plane_normal(const PlaneOrientation& o);

// The same from degrees, as orientations arrive at the program's boundary
// (scene files, picks, tests): dip and dip direction in degrees.
Eigen::Vector3d plane_normal_deg(double dip_deg, double dipdir_deg);

// Dip / dip direction of the plane with normal n (either sense; n need not be
// unit). For a vertical plane the dip direction is the azimuth n points to.
PlaneOrientation plane_orientation(const Eigen::Vector3d& n);

// Unit vector of a line: (cos p sin t, cos p cos t, -sin p).
Eigen::Vector3d line_direction(const LineOrientation& o);

// Trend / plunge of direction d (need not be unit), keeping its sense: an
// upward d has negative plunge.
LineOrientation line_orientation(const Eigen::Vector3d& d);

}  // namespace rockface::geometry
