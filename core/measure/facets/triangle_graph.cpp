#include "core/measure/facets/triangle_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/common/error.h"

namespace rockface::measure {

namespace {

struct EdgeUse {
  std::uint64_t key;  // lower vertex << 32 | higher vertex
  int triangle;
  int side;  // the edge is opposite this vertex of the triangle
};

}  // namespace

TriangleGraph triangle_graph(const photogrammetry::SurfaceMesh& mesh) {
  constexpr int kBorder = TriangleGraph::kBorder, kSharedByMore = TriangleGraph::kSharedByMore;
  const std::size_t n = mesh.triangles.size();
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw InputError("mesh", "more than 2^31 triangles: too large for facet search");
  TriangleGraph g;
  g.normals.assign(n, Eigen::Vector3d::Zero());
  g.centres.assign(n, Eigen::Vector3d::Zero());
  g.areas.assign(n, 0.0);
  g.neighbours.assign(n, {kBorder, kBorder, kBorder});
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  std::vector<EdgeUse> edges;
  edges.reserve(3 * n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    bool valid = true;
    for (int v : tri) valid = valid && v >= 0 && v < vertex_count && mesh.vertices[v].allFinite();
    if (!valid || tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double norm = cross.norm();
    if (!(norm > 0)) continue;
    g.normals[t] = cross / norm;
    g.areas[t] = 0.5 * norm;
    g.centres[t] = (a + b + c) / 3.0;
    for (int side = 0; side < 3; ++side) {
      const auto u = static_cast<std::uint32_t>(tri[(side + 1) % 3]);
      const auto w = static_cast<std::uint32_t>(tri[(side + 2) % 3]);
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(u, w)) << 32) | std::max(u, w);
      edges.push_back({key, static_cast<int>(t), side});
    }
  }
  // The uses of each edge: grouped by their lower vertex (a counting sort
  // over the vertices), then matched on their higher vertex within the
  // group, a few uses long on a lattice. The pairs a sort of all the keys
  // finds, without sorting millions of them.
  const auto lower = [](const EdgeUse& e) { return static_cast<std::size_t>(e.key >> 32); };
  std::vector<std::size_t> group_start(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (const EdgeUse& e : edges) ++group_start[lower(e) + 1];
  for (std::size_t v = 0; v + 1 < group_start.size(); ++v) group_start[v + 1] += group_start[v];
  std::vector<const EdgeUse*> by_lower(edges.size());
  {
    std::vector<std::size_t> fill(group_start.begin(), group_start.end() - 1);
    for (const EdgeUse& e : edges) by_lower[fill[lower(e)]++] = &e;
  }
  for (std::size_t v = 0; v + 1 < group_start.size(); ++v)
    for (std::size_t a = group_start[v]; a < group_start[v + 1]; ++a) {
      const EdgeUse& use = *by_lower[a];
      int uses = 0;
      const EdgeUse* other = nullptr;
      for (std::size_t b = group_start[v]; b < group_start[v + 1]; ++b)
        if (by_lower[b]->key == use.key) {
          ++uses;
          if (b != a) other = by_lower[b];
        }
      // A manifold edge: exactly two triangles share it. More than two:
      // no neighbour either, marked as such (the outlines' boundary test
      // needs to tell it from the surface's border).
      if (uses == 2) g.neighbours[use.triangle][use.side] = other->triangle;
      if (uses > 2) g.neighbours[use.triangle][use.side] = kSharedByMore;
    }
  return g;
}

std::vector<Eigen::Vector3d> smoothed_normals(const TriangleGraph& g, int passes) {
  std::vector<Eigen::Vector3d> current(g.size());
  for (std::size_t t = 0; t < g.size(); ++t) current[t] = g.normals[t] * g.areas[t];
  std::vector<Eigen::Vector3d> next(g.size());
  // Each pass averages with the edge neighbours (a diffusion of the
  // area-weighted normals): cheap, and on a lattice mesh close to a
  // Gaussian of sqrt(passes) triangles.
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t t = 0; t < g.size(); ++t) {
      if (!g.usable(t)) {
        next[t].setZero();
        continue;
      }
      Eigen::Vector3d sum = current[t];
      for (int k : g.neighbours[t])
        if (k >= 0) sum += current[k].dot(g.normals[t]) < 0 ? -current[k] : current[k];
      // Renormalised each pass (area-weighted again), so that many passes
      // neither overflow nor let large triangles dominate.
      const double norm = sum.norm();
      next[t] = norm > 0 ? Eigen::Vector3d(sum * (g.areas[t] / norm)) : Eigen::Vector3d::Zero();
    }
    std::swap(current, next);
  }
  for (std::size_t t = 0; t < g.size(); ++t) {
    const double norm = current[t].norm();
    current[t] = norm > 0 ? Eigen::Vector3d(current[t] / norm) : Eigen::Vector3d::Zero();
  }
  return current;
}

std::vector<float> bending(const TriangleGraph& g, const std::vector<Eigen::Vector3d>& normals) {
  std::vector<float> out(g.size(), static_cast<float>(M_PI));
  for (std::size_t t = 0; t < g.size(); ++t) {
    if (!g.usable(t)) continue;
    double least_cos = 1.0;
    for (int k : g.neighbours[t])
      if (k >= 0 && g.usable(static_cast<std::size_t>(k)))
        least_cos = std::min(least_cos, std::abs(normals[t].dot(normals[k])));
    out[t] = static_cast<float>(std::acos(std::clamp(least_cos, -1.0, 1.0)));
  }
  return out;
}

}  // namespace rockface::measure
