#include "core/blocks/point_location.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "core/blocks/tolerances.h"
#include "core/blocks/triangulation.h"

namespace rockface::blocks {

namespace {

// Closest point on triangle (a, b, c) to p (Ericson, Real-Time Collision
// Detection, 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

double distance_to_surface(const Polyhedron& block, const Eigen::Vector3d& point) {
  const auto& x = block.vertices();
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : triangulate(block).triangles)
    best = std::min(best, (closest_on_triangle(point, x[t[0]], x[t[1]], x[t[2]]) - point).norm());
  return best;
}

PointLocation locate_point(const Polyhedron& block, const Eigen::Vector3d& point,
                           double tolerance) {
  const double tol = tolerance >= 0 ? tolerance : kOnSurfaceRel * block.size();
  if (distance_to_surface(block, point) <= tol) return PointLocation::OnSurface;
  // Winding number: the solid angles of the surface triangles seen from the
  // point (Van Oosterom & Strackee) sum to 4 pi inside and 0 outside.
  const auto& x = block.vertices();
  double omega = 0;
  for (const Triangle& t : triangulate(block).triangles) {
    const Eigen::Vector3d a = x[t[0]] - point, b = x[t[1]] - point, c = x[t[2]] - point;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    omega += 2 * std::atan2(a.dot(b.cross(c)),
                            la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return omega > 2 * std::numbers::pi ? PointLocation::Inside : PointLocation::Outside;
}

}  // namespace rockface::blocks
