#include "core/blocks/triangulation.h"

#include <cmath>
#include <limits>

#include "core/blocks/face_frame.h"
#include "core/blocks/tolerances.h"
#include "core/common/error.h"
#include "core/geometry/cross2.h"

namespace rockface::blocks {

using geometry::cross2;

namespace {

// Whether p lies inside or on triangle (a, b, c) (counter-clockwise), with
// the edges widened by tol.
bool in_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                 const Eigen::Vector2d& c, double tol) {
  auto side = [&](const Eigen::Vector2d& s, const Eigen::Vector2d& e) {
    const Eigen::Vector2d d = e - s;
    const double len = d.norm();
    return len > 0 ? cross2(d, p - s) / len : 0.0;
  };
  return side(a, b) >= -tol && side(b, c) >= -tol && side(c, a) >= -tol;
}

}  // namespace

std::vector<Triangle> triangulate_face(const Polyhedron& block, int f) {
  const auto& loop = block.faces()[f].loop;
  const FaceFrame fr = face_frame(block, f);
  std::vector<int> idx(loop.size());
  for (size_t k = 0; k < loop.size(); ++k) idx[k] = static_cast<int>(k);
  std::vector<Triangle> out;
  const double tol = kConvexityRel * block.size();
  // A strictly convex loop (every corner turning left): a fan from its
  // first corner, O(n). Ear clipping below is O(n^3) and only for the rest.
  {
    const int n = static_cast<int>(idx.size());
    bool convex = true;
    for (int k = 0; k < n && convex; ++k) {
      const Eigen::Vector2d& a = fr.corners[(k + n - 1) % n];
      const Eigen::Vector2d& b = fr.corners[k];
      const Eigen::Vector2d& c = fr.corners[(k + 1) % n];
      convex = cross2(b - a, c - b) > tol * (c - a).norm();
    }
    if (convex) {
      for (int k = 1; k + 1 < n; ++k) out.push_back({loop[0], loop[k], loop[k + 1]});
      return out;
    }
  }
  while (idx.size() > 3) {
    const int n = static_cast<int>(idx.size());
    // Best ear: a convex corner whose triangle holds no other corner; among
    // those the one with the largest angle margin (fewest slivers). A
    // corner on a straight line (zero-area ear) only when nothing else is.
    int best = -1;
    double best_quality = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d& a = fr.corners[idx[(k + n - 1) % n]];
      const Eigen::Vector2d& b = fr.corners[idx[k]];
      const Eigen::Vector2d& c = fr.corners[idx[(k + 1) % n]];
      const double area2 = cross2(b - a, c - b);
      const double scale = (b - a).norm() * (c - b).norm();
      if (!(scale > 0)) continue;
      const double sine = area2 / scale;
      if (area2 < -tol * (c - a).norm()) continue;  // reflex corner
      bool blocked = false;
      for (int m = 0; m < n && !blocked; ++m) {
        if (m == k || m == (k + n - 1) % n || m == (k + 1) % n) continue;
        const Eigen::Vector2d& p = fr.corners[idx[m]];
        // Another corner at the same place as an ear corner does not block.
        if ((p - a).norm() <= tol || (p - c).norm() <= tol) continue;
        if (area2 > 0 && in_triangle(p, a, b, c, -tol)) blocked = true;
      }
      if (blocked) continue;
      if (sine > best_quality) {
        best_quality = sine;
        best = k;
      }
    }
    if (best < 0)
      throw Error("block " + block.id() + ": face " + std::to_string(f) +
                  " cannot be triangulated (its loop crosses itself)");
    out.push_back({loop[idx[(best + n - 1) % n]], loop[idx[best]], loop[idx[(best + 1) % n]]});
    idx.erase(idx.begin() + best);
  }
  out.push_back({loop[idx[0]], loop[idx[1]], loop[idx[2]]});
  return out;
}

Triangulation triangulate(const Polyhedron& block) {
  Triangulation t;
  for (int f = 0; f < static_cast<int>(block.faces().size()); ++f)
    for (const Triangle& tri : triangulate_face(block, f)) {
      t.triangles.push_back(tri);
      t.face_of.push_back(f);
    }
  return t;
}

}  // namespace rockface::blocks
