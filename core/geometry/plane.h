#pragma once
// A plane n . x = offset with unit upward normal n (the normal of its
// orientation), and the half-space codes of Goodman & Shi.
#include <Eigen/Core>

#include "core/geometry/orientation.h"

namespace rockface::geometry {

// Code 0 = upper = the side n points to; 1 = lower; 2 = plane not involved.
enum class HalfSpace : int { Upper = 0, Lower = 1, NotInvolved = 2 };

// +1 for Upper, -1 for Lower, 0 for NotInvolved: multiplies n into the normal
// that points into the half-space.
inline double side_sign(HalfSpace h) {
  return h == HalfSpace::Upper ? 1.0 : (h == HalfSpace::Lower ? -1.0 : 0.0);
}
inline char code_digit(HalfSpace h) { return static_cast<char>('0' + static_cast<int>(h)); }

struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, upward (z >= 0)
  double offset = 0;                                  // n . x on the plane

  static Plane from_orientation(const PlaneOrientation& o, const Eigen::Vector3d& point) {
    Plane p;
    p.normal = plane_normal(o);
    p.offset = p.normal.dot(point);
    return p;
  }
  // Positive on the upper side.
  double signed_distance(const Eigen::Vector3d& x) const { return normal.dot(x) - offset; }
  // The normal pointing into half-space h (zero for NotInvolved).
  Eigen::Vector3d inward_normal(HalfSpace h) const { return side_sign(h) * normal; }
  // The same plane seen from a datum: coordinates x' = x - datum.
  Plane shifted(const Eigen::Vector3d& datum) const { return {normal, offset - normal.dot(datum)}; }
};

}  // namespace rockface::geometry
