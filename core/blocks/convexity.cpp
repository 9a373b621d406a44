#include "core/blocks/convexity.h"

#include "core/blocks/face_frame.h"
#include "core/blocks/tolerances.h"
#include "core/geometry/cross2.h"

namespace rockface::blocks {

using geometry::cross2;

bool face_is_convex(const Polyhedron& block, int f) {
  const FaceFrame fr = face_frame(block, f);
  const int n = static_cast<int>(fr.corners.size());
  const double tol = kConvexityRel * block.size();
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = fr.corners[(k + n - 1) % n];
    const Eigen::Vector2d& b = fr.corners[k];
    const Eigen::Vector2d& c = fr.corners[(k + 1) % n];
    // Signed distance of c from the line a -> b: negative turns clockwise.
    const Eigen::Vector2d ab = b - a;
    const double len = ab.norm();
    if (len > 0 && cross2(ab, c - b) / len < -tol) return false;
  }
  return true;
}

bool is_convex(const Polyhedron& block) {
  const double tol = kConvexityRel * block.size();
  for (int f = 0; f < static_cast<int>(block.faces().size()); ++f) {
    if (!face_is_convex(block, f)) return false;
    const auto& bp = block.planes()[block.faces()[f].plane];
    const Eigen::Vector3d out = bp.outward_normal();
    const Eigen::Vector3d& p0 = block.vertices()[block.faces()[f].loop[0]];
    for (const auto& x : block.vertices())
      if ((x - p0).dot(out) > tol) return false;
  }
  return true;
}

}  // namespace rockface::blocks
