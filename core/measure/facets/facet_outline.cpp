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
  //
  // The edges are kept in flat arrays grouped by hash bucket, the buckets
  // a std::unordered_map<std::uint64_t, int> reserved for all of them would
  // have (key modulo its prime bucket count): one pass to count, one to
  // place, no allocation per edge (the map's nodes were a quarter of facet
  // search on a 24 Mpx model). The boundary edges then enter `next` in the
  // order that map's iteration gave them (the bucket first filled last
  // first, within a bucket the latest edge first), so that each loop
  // starts, and each pinch vertex is left, where it was: outlines and their
  // thinning unchanged.
  auto key = [](int u, int v) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) |
           static_cast<std::uint32_t>(v);
  };
  const std::size_t edge_count = 3 * triangles.size();
  const std::size_t bucket_count = [edge_count] {
    std::unordered_map<std::uint64_t, int> probe;
    probe.reserve(edge_count);
    return probe.bucket_count();
  }();
  std::vector<std::uint64_t> keys(edge_count);       // in the order the triangles list them
  std::vector<std::uint32_t> bucket_of(edge_count);  // the modulo, taken once
  std::vector<std::uint32_t> bucket_start(bucket_count + 1, 0);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(triangles[i])];
    for (int s = 0; s < 3; ++s) {
      const std::size_t e = 3 * i + static_cast<std::size_t>(s);
      keys[e] = key(tri[s], tri[(s + 1) % 3]);
      bucket_of[e] = static_cast<std::uint32_t>(keys[e] % bucket_count);
      ++bucket_start[bucket_of[e] + 1];
    }
  }
  for (std::size_t b = 0; b < bucket_count; ++b) bucket_start[b + 1] += bucket_start[b];
  // Each bucket's edges (indices into keys), in the order they came.
  std::vector<std::uint32_t> in_bucket(edge_count);
  {
    std::vector<std::uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (std::size_t i = 0; i < edge_count; ++i)
      in_bucket[fill[bucket_of[i]]++] = static_cast<std::uint32_t>(i);
  }
  // The first edge with key k, in its bucket b (edge_count: none).
  const auto first_with = [&](std::uint64_t k, std::size_t b) -> std::size_t {
    for (std::uint32_t j = bucket_start[b]; j < bucket_start[b + 1]; ++j)
      if (keys[in_bucket[j]] == k) return in_bucket[j];
    return edge_count;
  };
  struct BoundaryEdge {
    std::uint32_t bucket_first;  // the first edge of its bucket
    std::uint32_t first;         // its own first occurrence
    int from, to;
  };
  std::vector<BoundaryEdge> boundary;
  for (std::size_t i = 0; i < edge_count; ++i) {
    const int u = static_cast<int>(keys[i] >> 32), v = static_cast<int>(keys[i] & 0xffffffffu);
    const std::uint64_t reverse = key(v, u);
    if (first_with(keys[i], bucket_of[i]) != i ||
        first_with(reverse, reverse % bucket_count) != edge_count)
      continue;
    boundary.push_back(
        {in_bucket[bucket_start[bucket_of[i]]], static_cast<std::uint32_t>(i), u, v});
  }
  std::sort(boundary.begin(), boundary.end(), [](const BoundaryEdge& x, const BoundaryEdge& y) {
    return x.bucket_first != y.bucket_first ? x.bucket_first > y.bucket_first : x.first > y.first;
  });
  std::unordered_multimap<int, int> next;  // boundary: from -> to
  for (const BoundaryEdge& e : boundary) next.emplace(e.from, e.to);
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
