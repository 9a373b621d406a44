#pragma once
// Comparing measured planes with true ones in tests: a plane's pole from its
// dip / dip direction in degrees (geometry::plane_normal), and the angle
// between two planes (their poles in either sense), in degrees.
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "core/common/units.h"
#include "core/geometry/orientation.h"

namespace rockface::test {

inline Eigen::Vector3d pole_of(double dip_deg, double dipdir_deg) {
  return geometry::plane_normal_deg(dip_deg, dipdir_deg);
}

inline double plane_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

}  // namespace rockface::test
