#include "firmware-app/export/block_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <map>

namespace rockface::app {

std::optional<std::vector<std::array<int, 3>>> convex_hull_triangles(
    const std::vector<Eigen::Vector3d>& corners) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  if (corners.size() < 4) return std::nullopt;
  // About the first corner: survey coordinates (10^6 m) would leave the
  // predicates' filters few digits for a block of a metre.
  const Eigen::Vector3d origin = corners.front();
  std::vector<Point> points;
  std::map<std::array<double, 3>, int> index;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector3d p = corners[i] - origin;
    points.emplace_back(p.x(), p.y(), p.z());
    index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, static_cast<int>(i));
  }
  CGAL::Surface_mesh<Point> hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  if (hull.number_of_faces() < 4) return std::nullopt;  // flat: a polygon, not a block
  std::vector<std::array<int, 3>> triangles;
  for (const auto f : hull.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      if (k == 3) return std::nullopt;  // convex_hull_3 triangulates: never more
      const Point& p = hull.point(v);
      // The hull's vertices are copies of the input points: found exactly.
      const auto it = index.find({p.x(), p.y(), p.z()});
      if (it == index.end()) return std::nullopt;
      t[k++] = it->second;
    }
    if (k != 3) return std::nullopt;
    triangles.push_back(t);
  }
  return triangles;
}

}  // namespace rockface::app
