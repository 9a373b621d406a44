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

BestPlane best_plane(std::span<const Eigen::Vector3d> points) {
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

namespace {

// A corner whose nearest neighbour is more than this many times the middle
// corner's is alone amid another surface (see the edge test).
constexpr float kLoneCorner = 3;

void require_meshable(std::size_t points) {
  if (points < 3)
    throw InputError("point cloud",
                     std::to_string(points) + " points: a surface needs three at least");
  if (points > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InputError("point cloud", "more points than a mesh can index");
}

}  // namespace

CloudMesh mesh_point_cloud(std::span<const Eigen::Vector3d> points,
                           const CloudMeshingOptions& options) {
  require_meshable(points.size());
  const BestPlane plane = best_plane(points);
  const Eigen::Vector3d u = plane.u;
  // (u, v, normal) right-handed: counter-clockwise in (u, v) is
  // counter-clockwise seen from +normal.
  const Eigen::Vector3d v = plane.normal.cross(u);
  std::vector<Eigen::Vector2d> uv(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - plane.centroid;
    uv[i] = {d.dot(u), d.dot(v)};
  }
  CloudMesh out = mesh_point_cloud_on(points, uv, options);
  out.centroid = plane.centroid;
  out.normal = plane.normal;
  return out;
}

CloudMesh mesh_point_cloud_on(std::span<const Eigen::Vector3d> points,
                              const std::vector<Eigen::Vector2d>& uv,
                              const CloudMeshingOptions& options) {
  return mesh_point_cloud_on(points, uv, {}, options);
}

CloudMesh mesh_point_cloud_on(std::span<const Eigen::Vector3d> points,
                              const std::vector<Eigen::Vector2d>& uv,
                              const std::vector<int>& repeated,
                              const CloudMeshingOptions& options) {
  using namespace cloud_meshing_detail;
  require_meshable(uv.size());
  if (uv.size() != points.size() + repeated.size())
    throw InputError("point cloud", std::to_string(uv.size()) + " surface coordinates for " +
                                        std::to_string(points.size()) + " points and " +
                                        std::to_string(repeated.size()) + " repeated");
  for (const int r : repeated)
    if (r < 0 || static_cast<std::size_t>(r) >= points.size())
      throw InputError("point cloud", "a repeated point " + std::to_string(r) + " of " +
                                          std::to_string(points.size()));
  // The point at surface place k.
  const std::size_t own = points.size();
  const auto xyz = [&](std::uint32_t k) -> const Eigen::Vector3d& {
    return k < own ? points[k] : points[static_cast<std::size_t>(repeated[k - own])];
  };
  CloudMesh out;
  // The points' order along u: the cloud is triangulated strip by strip
  // along u, so that the triangulation in memory is one strip's (CGAL's
  // takes some 160 bytes a point: a 10-million-point cloud at once would not
  // fit the tablet's 2 GB).
  double lo_u = std::numeric_limits<double>::infinity(), hi_u = -lo_u, lo_v = lo_u, hi_v = -lo_u;
  for (const auto& p : uv) {
    lo_u = std::min(lo_u, p.x()), hi_u = std::max(hi_u, p.x());
    lo_v = std::min(lo_v, p.y()), hi_v = std::max(hi_v, p.y());
  }
  std::vector<std::uint32_t> order(uv.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return uv[a].x() < uv[b].x(); });
  // A strip overlaps its neighbours by many point spacings (the spacing
  // guessed from the extent, an overestimate where the cloud has holes): a
  // kept triangle (edges of a few spacings) near the strip's edge sees the
  // same neighbours as in one triangulation of the whole.
  const double guessed_spacing = std::sqrt(
      std::max(hi_u - lo_u, 1e-9) * std::max(hi_v - lo_v, 1e-9) / static_cast<double>(uv.size()));
  const double margin = options.strip_overlap_spacings * guessed_spacing;

  std::vector<bool> used(points.size(), false);  // per point, at either place
  constexpr float kNone = std::numeric_limits<float>::infinity();
  std::vector<float> nearest(uv.size(), kNone);  // per place
  std::vector<float> spacing_sample;
  out.triangles.reserve(2 * uv.size());
  const std::size_t strip = std::max<std::size_t>(options.strip_points, 1000);
  for (std::size_t first = 0; first < order.size(); first += strip) {
    const std::size_t last = std::min(order.size(), first + strip);  // the core: [first, last)
    const double core_lo =
        first == 0 ? -std::numeric_limits<double>::infinity() : uv[order[first]].x();
    const double core_hi =
        last == order.size() ? std::numeric_limits<double>::infinity() : uv[order[last]].x();
    auto at_u = [&](double value) {
      return static_cast<std::size_t>(
          std::lower_bound(order.begin(), order.end(), value,
                           [&](std::uint32_t i, double x) { return uv[i].x() < x; }) -
          order.begin());
    };
    const std::size_t from = first == 0 ? 0 : at_u(core_lo - margin);
    const std::size_t to = last == order.size() ? order.size() : at_u(core_hi + margin);

    Delaunay dt;
    {
      std::vector<std::pair<Kernel::Point_2, std::uint32_t>> projected;
      projected.reserve(to - from);
      for (std::size_t k = from; k < to; ++k)
        projected.emplace_back(Kernel::Point_2(uv[order[k]].x(), uv[order[k]].y()), order[k]);
      dt.insert(projected.begin(), projected.end());  // spatially sorted inside
    }
    // Each point's nearest neighbour, in 3D, over its Delaunay edges (exact
    // for the points near the core: their neighbours are all in the strip).
    for (std::size_t k = from; k < to; ++k) nearest[order[k]] = kNone;  // this strip's own
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const auto a = e->first->vertex(Delaunay::cw(e->second))->info();
      const auto b = e->first->vertex(Delaunay::ccw(e->second))->info();
      const auto d = static_cast<float>((xyz(a) - xyz(b)).norm());
      nearest[a] = std::min(nearest[a], d);
      nearest[b] = std::min(nearest[b], d);
    }
    const std::size_t stride = std::max<std::size_t>(1, uv.size() / 100000);
    for (std::size_t k = first; k < last; k += stride)
      if (std::isfinite(nearest[order[k]])) spacing_sample.push_back(nearest[order[k]]);
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const std::array<std::uint32_t, 3> idx{f->vertex(0)->info(), f->vertex(1)->info(),
                                             f->vertex(2)->info()};
      // The strip whose core holds the centroid keeps the triangle.
      const double cu = (uv[idx[0]].x() + uv[idx[1]].x() + uv[idx[2]].x()) / 3;
      if (cu < core_lo || cu >= core_hi) continue;
      double longest = 0;
      std::array<float, 3> corner_spacing{};
      for (std::size_t k = 0; k < 3; ++k) {
        longest = std::max(longest, (xyz(idx[k]) - xyz(idx[(k + 1) % 3])).norm());
        corner_spacing[k] = nearest[idx[k]];
      }
      // The largest of the corners' spacings, but at most kLoneCorner times
      // the middle one: a corner alone amid another surface (a point of the
      // rock seen past a plate in front of it, all its 2D neighbours on the
      // plate) has a nearest neighbour as far as the plate, and with the
      // largest alone its curtain from the plate to the rock was kept (issue
      // 43: a tap on the range pole's plate met it 9 cm off). The middle
      // alone dropped a noisy scan's own triangles (3 mm of noise at 2.8 mm
      // spacing: 850 k points of 9.8 M left in no triangle, 134 k with the
      // largest).
      std::sort(corner_spacing.begin(), corner_spacing.end());
      const float spacing = std::min(corner_spacing[2], kLoneCorner * corner_spacing[1]);
      if (longest > options.max_edge_to_spacing * spacing) {
        ++out.dropped_triangles;
        continue;
      }
      out.triangles.push_back(
          {static_cast<int>(idx[0]), static_cast<int>(idx[1]), static_cast<int>(idx[2])});
      for (auto i : idx) used[i < own ? i : static_cast<std::size_t>(repeated[i - own])] = true;
    }
  }
  if (!spacing_sample.empty()) {
    auto mid = spacing_sample.begin() + static_cast<std::ptrdiff_t>(spacing_sample.size() / 2);
    std::nth_element(spacing_sample.begin(), mid, spacing_sample.end());
    out.median_spacing = *mid;
  }
  out.unused_points = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
  return out;
}

}  // namespace rockface::photogrammetry
