#include "core/blocks/slab_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/parallel_planes.h"

namespace rockface::blocks {

std::vector<SlabPair> slab_pairs(const std::vector<HalfSpaceInput>& halfspaces, double tolerance,
                                 const Eigen::Vector3d& centre, double reach) {
  // Inward form n . x >= b.
  std::vector<Eigen::Vector3d> n;
  std::vector<double> b;
  for (const auto& h : halfspaces) {
    const double s = geometry::side_sign(h.side) / h.plane.normal.norm();
    n.push_back(s * h.plane.normal);
    b.push_back(s * h.plane.offset);
  }
  std::vector<SlabPair> out;
  for (const auto& [i, j] : geometry::opposite_pairs(n, tolerance)) {
    SlabPair p;
    p.first = i;
    p.second = j;
    const double g = n[i].dot(n[j]);
    p.angle = std::acos(std::clamp(-g, -1.0, 1.0));
    // The point of their common line nearest the centre, x = centre +
    // alpha n_i + beta n_j on both planes; the 2x2 system's determinant
    // 1 - g^2 is the squared sine of their angle: zero when parallel.
    const double det = 1 - g * g;
    if (!(det > 0)) {
      p.meet_distance = std::numeric_limits<double>::infinity();
    } else {
      const double ri = b[i] - n[i].dot(centre), rj = b[j] - n[j].dot(centre);
      const double alpha = (ri - g * rj) / det, beta = (rj - g * ri) / det;
      p.meet_distance = (alpha * n[i] + beta * n[j]).norm();
    }
    if (p.meet_distance > reach) out.push_back(p);
  }
  return out;
}

}  // namespace rockface::blocks
