#include "core/measure/facets/facet_outline.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

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

namespace {

std::uint64_t edge_key(int u, int v) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) |
         static_cast<std::uint32_t>(v);
}

// The buckets a std::unordered_map<std::uint64_t, int> reserved for
// `count` elements has.
std::size_t map_bucket_count(std::size_t count) {
  std::unordered_map<std::uint64_t, int> probe;
  probe.reserve(count);
  return probe.bucket_count();
}

struct BoundaryEdge {
  std::uint32_t bucket_first;  // the first edge of its bucket
  std::uint32_t first;         // its own first occurrence
  int from, to;
};

// The boundary edges from every edge's key: grouped in flat arrays by hash
// bucket (one pass to count, one to place), each looked up with its
// reverse.
std::vector<BoundaryEdge> boundary_by_keys(const photogrammetry::SurfaceMesh& mesh,
                                           const std::vector<int>& triangles,
                                           std::size_t bucket_count) {
  const std::size_t edge_count = 3 * triangles.size();
  std::vector<std::uint64_t> keys(edge_count);       // in the order the triangles list them
  std::vector<std::uint32_t> bucket_of(edge_count);  // the modulo, taken once
  std::vector<std::uint32_t> bucket_start(bucket_count + 1, 0);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(triangles[i])];
    for (int s = 0; s < 3; ++s) {
      const std::size_t e = 3 * i + static_cast<std::size_t>(s);
      keys[e] = edge_key(tri[s], tri[(s + 1) % 3]);
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
  std::vector<BoundaryEdge> boundary;
  for (std::size_t i = 0; i < edge_count; ++i) {
    const int u = static_cast<int>(keys[i] >> 32), v = static_cast<int>(keys[i] & 0xffffffffu);
    const std::uint64_t reverse = edge_key(v, u);
    if (first_with(keys[i], bucket_of[i]) != i ||
        first_with(reverse, reverse % bucket_count) != edge_count)
      continue;
    boundary.push_back(
        {in_bucket[bucket_start[bucket_of[i]]], static_cast<std::uint32_t>(i), u, v});
  }
  return boundary;
}

// The same boundary edges read off the triangle graph: an edge is on the
// boundary unless the triangle across it is a member too and runs it the
// other way (the same way: the earlier of the two is the boundary's, as
// the first occurrence of its key). Only the boundary edges' buckets are
// then looked for among all the edges. False (nothing read) when an edge
// is shared by more than two triangles: the graph does not say which.
// `position`: -1 for every triangle of the graph; left so.
bool boundary_by_graph(const photogrammetry::SurfaceMesh& mesh, const TriangleGraph& graph,
                       const std::vector<int>& triangles, std::size_t bucket_count,
                       std::vector<int>& position, std::vector<BoundaryEdge>& boundary) {
  // A triangle listed twice: its copies' edges are duplicates of each
  // other, which the graph does not see.
  bool known = true;
  std::size_t placed = 0;
  for (; placed < triangles.size() && known; ++placed) {
    known = position[triangles[placed]] < 0;
    position[triangles[placed]] = static_cast<int>(placed);
  }
  for (std::size_t i = 0; i < triangles.size() && known; ++i) {
    const int t = triangles[i];
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    for (int s = 0; s < 3; ++s) {
      const int u = tri[s], v = tri[(s + 1) % 3];
      // The graph's side is the one opposite the edge's third vertex.
      const int k = graph.neighbours[static_cast<std::size_t>(t)][(s + 2) % 3];
      if (k == TriangleGraph::kSharedByMore) {
        known = false;
        break;
      }
      const std::uint32_t e = static_cast<std::uint32_t>(3 * i + static_cast<std::size_t>(s));
      if (k >= 0 && position[k] >= 0) {
        const auto& other = mesh.triangles[static_cast<std::size_t>(k)];
        int same = -1;
        for (int o = 0; o < 3; ++o)
          if (other[o] == u && other[(o + 1) % 3] == v) same = o;
        if (same < 0) continue;  // run the other way: inside the facet
        if (3 * static_cast<std::size_t>(position[k]) + static_cast<std::size_t>(same) < e)
          continue;  // the same way, and the other is the first
      }
      boundary.push_back({0, e, u, v});
    }
  }
  for (std::size_t i = 0; i < placed; ++i) position[triangles[i]] = -1;
  if (!known) {
    boundary.clear();
    return false;
  }
  // Each boundary edge's bucket's first edge among all the facet's edges.
  std::vector<char> wanted(bucket_count, 0), seen(bucket_count, 0);
  for (const BoundaryEdge& b : boundary) wanted[edge_key(b.from, b.to) % bucket_count] = 1;
  std::vector<std::uint32_t> first_of(bucket_count);  // read only where seen
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(triangles[i])];
    for (int s = 0; s < 3; ++s) {
      const std::size_t b = edge_key(tri[s], tri[(s + 1) % 3]) % bucket_count;
      if (wanted[b] && !seen[b]) {
        seen[b] = 1;
        first_of[b] = static_cast<std::uint32_t>(3 * i + static_cast<std::size_t>(s));
      }
    }
  }
  for (BoundaryEdge& b : boundary) b.bucket_first = first_of[edge_key(b.from, b.to) % bucket_count];
  return true;
}

}  // namespace

FacetOutline facet_outline(const photogrammetry::SurfaceMesh& mesh,
                           const std::vector<int>& triangles, double tolerance,
                           const TriangleGraph* graph, std::vector<int>* position) {
  // Directed boundary edges: an edge u->v of a member triangle whose
  // reverse v->u belongs to no member is on the boundary (triangles of a
  // lattice mesh are consistently wound).
  //
  // The boundary edges enter `next` in the order a
  // std::unordered_map<std::uint64_t, int> of every edge, reserved for all
  // of them, gave them when it was iterated (the bucket first filled last
  // first, within a bucket the latest edge first; a bucket is the key
  // modulo the map's prime bucket count), so that each loop starts, and
  // each pinch vertex is left, where it was: outlines and their thinning
  // unchanged since the map (whose nodes were a quarter of facet search on
  // a 24 Mpx model) was replaced.
  const std::size_t bucket_count = map_bucket_count(3 * triangles.size());
  std::vector<BoundaryEdge> boundary;
  if (!graph || !position ||
      !boundary_by_graph(mesh, *graph, triangles, bucket_count, *position, boundary))
    boundary = boundary_by_keys(mesh, triangles, bucket_count);
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
