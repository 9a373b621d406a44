#include "core/measure/facets/facet_outline.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace rockface::measure {

namespace {

void thin(const std::vector<Eigen::Vector3d>& p, std::size_t from, std::size_t to, double tolerance,
          std::vector<char>& keep) {
  if (to <= from + 1) return;
  const Eigen::Vector3d a = p[from], b = p[to % p.size()];
  const Eigen::Vector3d d = b - a;
  const double len2 = d.squaredNorm();
  double worst = -1;
  std::size_t at = from;
  for (std::size_t i = from + 1; i < to; ++i) {
    const Eigen::Vector3d v = p[i] - a;
    const double t = len2 > 0 ? std::clamp(v.dot(d) / len2, 0.0, 1.0) : 0.0;
    const double dist = (v - t * d).norm();
    if (dist > worst) {
      worst = dist;
      at = i;
    }
  }
  if (worst <= tolerance) return;
  keep[at] = 1;
  thin(p, from, at, tolerance, keep);
  thin(p, at, to, tolerance, keep);
}

}  // namespace

std::vector<Eigen::Vector3d> thin_closed_polyline(const std::vector<Eigen::Vector3d>& loop,
                                                  double tolerance) {
  if (loop.size() <= 3 || tolerance <= 0) return loop;
  // Split the loop at its first point and the point farthest from it.
  std::size_t far = 0;
  for (std::size_t i = 1; i < loop.size(); ++i)
    if ((loop[i] - loop[0]).squaredNorm() > (loop[far] - loop[0]).squaredNorm()) far = i;
  std::vector<char> keep(loop.size(), 0);
  keep[0] = keep[far] = 1;
  thin(loop, 0, far, tolerance, keep);
  thin(loop, far, loop.size(), tolerance, keep);
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < loop.size(); ++i)
    if (keep[i]) out.push_back(loop[i]);
  return out;
}

FacetOutline facet_outline(const photogrammetry::SurfaceMesh& mesh,
                           const std::vector<int>& triangles, double tolerance) {
  // Directed boundary edges: an edge u->v of a member triangle whose
  // reverse v->u belongs to no member is on the boundary (triangles of a
  // lattice mesh are consistently wound).
  auto key = [](int u, int v) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) |
           static_cast<std::uint32_t>(v);
  };
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(3 * triangles.size());
  for (int t : triangles) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    for (int s = 0; s < 3; ++s) ++directed[key(tri[s], tri[(s + 1) % 3])];
  }
  std::unordered_multimap<int, int> next;  // boundary: from -> to
  for (const auto& [k, count] : directed) {
    const int u = static_cast<int>(k >> 32), v = static_cast<int>(k & 0xffffffffu);
    if (!directed.count(key(v, u))) next.emplace(u, v);
  }
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    auto it = next.begin();
    const int start = it->first;
    std::vector<int> loop{start};
    int at = it->second;
    next.erase(it);
    // Follow the boundary until it closes (a pinch vertex, where two loops
    // touch, is left by any of its outgoing edges: each edge is used once).
    while (at != start) {
      loop.push_back(at);
      auto out = next.find(at);
      if (out == next.end()) break;  // open chain (inconsistent winding): keep what we have
      at = out->second;
      next.erase(out);
    }
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  FacetOutline o;
  if (loops.empty()) return o;
  auto length = [&](const std::vector<int>& loop) {
    double sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
      sum += (mesh.vertices[loop[(i + 1) % loop.size()]] - mesh.vertices[loop[i]]).norm();
    return sum;
  };
  std::size_t outer = 0;
  double longest = -1;
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (const double l = length(loops[i]); l > longest) {
      longest = l;
      outer = i;
    }
  o.perimeter = longest;
  o.holes = static_cast<int>(loops.size()) - 1;
  std::vector<Eigen::Vector3d> points;
  for (int v : loops[outer]) points.push_back(mesh.vertices[v]);
  o.outer = thin_closed_polyline(points, tolerance);
  return o;
}

}  // namespace rockface::measure
