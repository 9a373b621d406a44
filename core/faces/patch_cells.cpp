#include "core/faces/patch_cells.h"

#include "core/faces/tolerances.h"
#include "core/geometry/cross2.h"

namespace rockface::faces {

using geometry::cross2;

// The part of a convex polygon where n . x >= c (keep) or <= c.
std::vector<Eigen::Vector2d> clip_convex(const std::vector<Eigen::Vector2d>& poly,
                                         const Eigen::Vector2d& n, double c, bool keep_upper) {
  std::vector<Eigen::Vector2d> out;
  const size_t m = poly.size();
  auto f = [&](const Eigen::Vector2d& x) { return keep_upper ? n.dot(x) - c : c - n.dot(x); };
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % m];
    const double fa = f(a), fb = f(b);
    if (fa >= 0) out.push_back(a);
    if ((fa >= 0) != (fb >= 0)) out.push_back(a + (b - a) * (fa / (fa - fb)));
  }
  return out;
}

double polygon_area(const std::vector<Eigen::Vector2d>& poly) {
  double a = 0;
  for (size_t i = 0; i < poly.size(); ++i) a += cross2(poly[i], poly[(i + 1) % poly.size()]);
  return a / 2;
}

double polygon_perimeter(const std::vector<Eigen::Vector2d>& poly) {
  double p = 0;
  for (size_t i = 0; i < poly.size(); ++i) p += (poly[(i + 1) % poly.size()] - poly[i]).norm();
  return p;
}

// The patch polygon cut by the trace lines of the given joint planes: the
// cells of their arrangement on the patch (2D, patch frame).
std::vector<std::vector<Eigen::Vector2d>> cut_by_planes(const SurfacePatch& P,
                                                        const std::vector<TraceBlockPlane>& planes,
                                                        const std::vector<int>& which) {
  std::vector<std::vector<Eigen::Vector2d>> cells{P.polygon2d};
  for (int j : which) {
    const geometry::Plane& pl = planes[j].plane;
    const Eigen::Vector2d n2(pl.normal.dot(P.e1), pl.normal.dot(P.e2));
    if (n2.norm() < kTraceOnPatchSine) continue;  // parallel to the patch: no line on it
    const double c = pl.offset - pl.normal.dot(P.origin);
    std::vector<std::vector<Eigen::Vector2d>> next;
    for (const auto& cell : cells)
      for (bool up : {true, false}) {
        auto part = clip_convex(cell, n2, c, up);
        if (part.size() >= 3 && polygon_area(part) > 0) next.push_back(std::move(part));
      }
    cells = std::move(next);
  }
  return cells;
}

}  // namespace rockface::faces
