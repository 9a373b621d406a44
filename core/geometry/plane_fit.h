#pragma once
// The best-fit plane of a point set by principal components (total least
// squares), with what a caller needs to judge it: the spread of the points
// off the plane, across their main line (the relief of a trace) and along it.
// The one plane fit of the project: trace planes (core/faces) and
// measurements on the 3D image (core/measure) both use it.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/orientation.h"
#include "core/geometry/plane.h"

namespace rockface::geometry {

struct PlaneFit {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, upward (DESIGN.md)
  Eigen::Vector3d line = Eigen::Vector3d::UnitX();    // direction of the largest spread
  // RMS distances of the points from the centroid along the principal axes,
  // smallest first: off the plane, across the main line within the plane (the
  // relief that fixes the plane's tilt about that line), along the line.
  Eigen::Vector3d spread = Eigen::Vector3d::Zero();
  std::size_t count = 0;

  double rms_off_plane() const { return spread(0); }
  double relief() const { return spread(1); }
  Plane plane() const { return {normal, normal.dot(centroid)}; }
  PlaneOrientation orientation() const { return plane_orientation(normal); }
  // One standard deviation (radians) of the normal's direction when each
  // point lies off the true plane with standard deviation `point_sigma`: the
  // tilt about the main line, sigma / (sqrt(n) relief), the weakest direction.
  double normal_sigma(double point_sigma) const;
};

// At least one point; three or more that are not collinear for a plane that
// means anything (check spread()).
PlaneFit fit_plane(const std::vector<Eigen::Vector3d>& points);

}  // namespace rockface::geometry
