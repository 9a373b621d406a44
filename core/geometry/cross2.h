#pragma once
// The z component of the cross product of two plane vectors: twice the
// signed area of the triangle they span, positive when b turns
// counter-clockwise from a. One definition for the libraries that each had
// their own copy (a unity build puts their files in one translation unit).
#include <Eigen/Core>

namespace rockface::geometry {

inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace rockface::geometry
