#include "core/photogrammetry/surface/cloud_meshing.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Eigenvalues>

#include "core/common/error.h"

namespace rockface::photogrammetry {

namespace cloud_meshing_detail {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using Structure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Structure>;

}  // namespace cloud_meshing_detail

BestPlane best_plane(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) throw InputError("point cloud", "no points");
  // A plane needs few of a million points: every k-th of 200000 at most.
  const std::size_t stride = std::max<std::size_t>(1, points.size() / 200000);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (std::size_t i = 0; i < points.size(); i += stride, ++n) sum += points[i];
  BestPlane out;
  out.centroid = sum / static_cast<double>(n);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < points.size(); i += stride) {
    const Eigen::Vector3d d = points[i] - out.centroid;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  // Eigenvalues ascending: the normal is the least spread, u the most.
  const Eigen::Vector3d spread = eig.eigenvalues();
  // 1e-12 of the largest spread: the points lie on one line (or one point).
  if (!(spread[1] > 1e-12 * spread[2]))
    throw InputError("point cloud", "the points lie on a line: they span no surface");
  out.normal = eig.eigenvectors().col(0).normalized();
  out.u = eig.eigenvectors().col(2).normalized();
  return out;
}

CloudMesh mesh_point_cloud(const std::vector<Eigen::Vector3d>& points,
                           const CloudMeshingOptions& options) {
  using namespace cloud_meshing_detail;
  if (points.size() < 3)
    throw InputError("point cloud",
                     std::to_string(points.size()) + " points: a surface needs three at least");
  if (points.size() > std::numeric_limits<std::int32_t>::max())
    throw InputError("point cloud", "more points than a mesh can index");
  CloudMesh out;
  const BestPlane plane = best_plane(points);
  out.centroid = plane.centroid;
  out.normal = plane.normal;
  const Eigen::Vector3d u = plane.u;
  // (u, v, normal) right-handed: counter-clockwise in (u, v) is
  // counter-clockwise seen from +normal.
  const Eigen::Vector3d v = plane.normal.cross(u);

  Delaunay dt;
  {
    std::vector<std::pair<Kernel::Point_2, std::uint32_t>> projected;
    projected.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d d = points[i] - out.centroid;
      projected.emplace_back(Kernel::Point_2(d.dot(u), d.dot(v)), static_cast<std::uint32_t>(i));
    }
    dt.insert(projected.begin(), projected.end());  // spatially sorted inside
  }
  // Each point's nearest neighbour, in 3D, over its Delaunay edges.
  std::vector<float> nearest(points.size(), std::numeric_limits<float>::infinity());
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto a = e->first->vertex(Delaunay::cw(e->second))->info();
    const auto b = e->first->vertex(Delaunay::ccw(e->second))->info();
    const auto d = static_cast<float>((points[a] - points[b]).norm());
    nearest[a] = std::min(nearest[a], d);
    nearest[b] = std::min(nearest[b], d);
  }
  {
    std::vector<float> sample;
    const std::size_t stride = std::max<std::size_t>(1, nearest.size() / 100000);
    for (std::size_t i = 0; i < nearest.size(); i += stride)
      if (std::isfinite(nearest[i])) sample.push_back(nearest[i]);
    if (!sample.empty()) {
      auto mid = sample.begin() + static_cast<std::ptrdiff_t>(sample.size() / 2);
      std::nth_element(sample.begin(), mid, sample.end());
      out.median_spacing = *mid;
    }
  }
  std::vector<bool> used(points.size(), false);
  out.triangles.reserve(2 * points.size());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const std::array<int, 3> tri{static_cast<int>(f->vertex(0)->info()),
                                 static_cast<int>(f->vertex(1)->info()),
                                 static_cast<int>(f->vertex(2)->info())};
    double longest = 0;
    float spacing = 0;
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::size_t>(tri[static_cast<std::size_t>(k)]);
      const auto b = static_cast<std::size_t>(tri[static_cast<std::size_t>((k + 1) % 3)]);
      longest = std::max(longest, (points[a] - points[b]).norm());
      spacing = std::max(spacing, nearest[a]);
    }
    if (longest > options.max_edge_to_spacing * spacing) {
      ++out.dropped_triangles;
      continue;
    }
    out.triangles.push_back(tri);
    for (int i : tri) used[static_cast<std::size_t>(i)] = true;
  }
  out.unused_points = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
  return out;
}

}  // namespace rockface::photogrammetry
