#include "core/faces/surface_loops.h"

#include "core/faces/union_find.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace rockface::faces {

namespace {

// The unfolded angle swept counter-clockwise from `from` to `to` at a vertex.
double sweep(double from, double to, double total) {
  double d = std::fmod(to - from, total);
  if (d < 0) d += total;
  return d;
}

double distance_to_polyline(const std::vector<Eigen::Vector3d>& line, const Eigen::Vector3d& x) {
  double best = line.empty() ? INFINITY : (line[0] - x).norm();
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Eigen::Vector3d d = line[i + 1] - line[i];
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((x - line[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (line[i] + t * d - x).norm());
  }
  return best;
}

// A face's corners in its patch's plane.
std::vector<Eigen::Vector2d> patch_polygon(const TraceNetwork& net, const SurfacePatch& patch,
                                           const std::vector<int>& half_edges) {
  std::vector<Eigen::Vector2d> poly;
  for (int g : half_edges) poly.push_back(patch.to2d(net.vertices()[net.origin(g)]));
  return poly;
}

// Which patch a face lies on (-1: outside the surface): the sector swept
// from the outgoing stretch to the way back, at the first corner.
int patch_at_first_corner(const TraceNetwork& net, const std::vector<int>& half_edges) {
  const int first = half_edges.front();
  const int v = net.target(first);
  const int nx = half_edges.size() > 1 ? half_edges[1] : net.next(first);
  const AroundVertex& av = net.around()[v];
  const double a_next = av.angle[net.slot(nx)], a_back = av.angle[net.slot(first ^ 1)];
  double width = sweep(a_next, a_back, av.total);
  if (width == 0) width = av.total;  // a dangling end: the face goes all the way round
  const double mid = std::fmod(a_next + width / 2, av.total);
  int patch = -1;
  for (const auto& s : av.sectors)
    if (mid > s.begin && mid < s.end) patch = s.patch;
  return patch;
}

// Signed area of a polygon (shoelace), counter-clockwise positive.
double signed_area(const std::vector<Eigen::Vector2d>& poly) {
  double a = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d p = poly[i], q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return a / 2;
}

// The faces by Lu's rule: each half-edge's next around its face, every
// half-edge in one face (half_edge_face), each face on its patch with its
// signed area.
std::vector<SurfaceFace> faces_by_lus_rule(const TraceNetwork& net, const FreeSurface& surface,
                                           std::vector<int>& half_edge_face) {
  std::vector<SurfaceFace> faces;
  const size_t nh = half_edge_face.size();
  for (size_t h0 = 0; h0 < nh; ++h0) {
    if (half_edge_face[h0] >= 0) continue;
    const int f = static_cast<int>(faces.size());
    SurfaceFace face;
    int h = static_cast<int>(h0);
    // A face has at most every half-edge once; the bound only guards the loop.
    for (size_t steps = 0; steps <= nh && half_edge_face[h] < 0; ++steps) {
      half_edge_face[h] = f;
      face.half_edges.push_back(h);
      h = net.next(h);
    }
    face.patch = patch_at_first_corner(net, face.half_edges);
    if (face.patch >= 0)
      face.area = signed_area(patch_polygon(net, surface.patches()[face.patch], face.half_edges));
    faces.push_back(std::move(face));
  }
  return faces;
}

// A face all of whose stretches have the face on both sides is the walk
// around a tree of traces (its area is zero up to rounding): made zero, a
// hole as an island's outside is.
void zero_the_walks_around_trees(std::vector<SurfaceFace>& faces,
                                 const std::vector<int>& half_edge_face) {
  const size_t nf = faces.size();
  std::vector<bool> tree(nf, true);
  for (size_t f = 0; f < nf; ++f)
    for (int h : faces[f].half_edges)
      if (half_edge_face[h ^ 1] != static_cast<int>(f)) tree[f] = false;
  for (size_t f = 0; f < nf; ++f)
    if (tree[f]) faces[f].area = 0;
}

// The smallest face of positive area on the hole's patch that holds the
// island's first corner; -1 if none does. The face around an island shares
// no corner with it (the island is a component of its own), so the island's
// corner lies strictly inside it; the island's own faces, which share
// corners, are not candidates.
int face_around_island(const TraceNetwork& net, const FreeSurface& surface,
                       const std::vector<SurfaceFace>& faces, const SurfaceFace& hole) {
  const SurfacePatch& P = surface.patches()[hole.patch];
  const Eigen::Vector2d p = P.to2d(net.vertices()[net.origin(hole.half_edges.front())]);
  std::vector<bool> on_island(net.vertices().size(), false);
  for (int g : hole.half_edges) on_island[net.origin(g)] = true;
  int best = -1;
  for (size_t g = 0; g < faces.size(); ++g) {
    const SurfaceFace& c = faces[g];
    if (c.patch != hole.patch || c.area <= 0) continue;
    if (best >= 0 && c.area >= faces[best].area) continue;
    bool touches = false;
    for (int k : c.half_edges) touches = touches || on_island[net.origin(k)];
    if (touches) continue;
    if (winding_number(patch_polygon(net, surface.patches()[c.patch], c.half_edges), p) != 0)
      best = static_cast<int>(g);
  }
  return best;
}

// The regions: the union's classes other than the outside's, numbered in
// the order of their first face, each with its faces, area and patches
// (ascending, once each).
void collect_regions(const std::vector<SurfaceFace>& faces, UnionFind& uf, int outside,
                     std::vector<int>& face_region, std::vector<SurfaceRegion>& regions) {
  const size_t nf = faces.size();
  std::vector<int> region_of_root(nf + 1, -1);
  face_region.assign(nf, -1);
  for (size_t f = 0; f < nf; ++f) {
    const int r = uf.find(static_cast<int>(f));
    if (r == uf.find(outside)) continue;
    if (region_of_root[r] < 0) {
      region_of_root[r] = static_cast<int>(regions.size());
      regions.push_back({});
    }
    const int reg = region_of_root[r];
    face_region[f] = reg;
    SurfaceRegion& region = regions[reg];
    region.faces.push_back(static_cast<int>(f));
    region.area += faces[f].area;
    if (faces[f].area > 0) region.patches.push_back(faces[f].patch);
  }
  for (SurfaceRegion& region : regions) {
    std::sort(region.patches.begin(), region.patches.end());
    region.patches.erase(std::unique(region.patches.begin(), region.patches.end()),
                         region.patches.end());
  }
}

// The loops of trace half-edges around a region (on_loop says which
// half-edges bound it), the outer one first: each walked by turning to the
// next loop stretch clockwise at every corner, ordered by their total turning.
template <typename OnLoop>
std::vector<std::vector<int>> loops_around_region(const TraceNetwork& net,
                                                  const std::vector<SurfaceFace>& faces,
                                                  const SurfaceRegion& region, size_t nh,
                                                  const OnLoop& on_loop) {
  std::vector<bool> used(nh, false);
  std::vector<std::pair<double, std::vector<int>>> cycles;
  for (int f : region.faces)
    for (int h0 : faces[f].half_edges) {
      if (!on_loop(h0) || used[h0]) continue;
      std::vector<int> cycle;
      double turning = 0;
      int h = h0;
      for (size_t steps = 0; steps <= nh && !used[h]; ++steps) {
        used[h] = true;
        cycle.push_back(h);
        const int v = net.target(h);
        const AroundVertex& av = net.around()[v];
        const int deg = static_cast<int>(av.half_edges.size());
        const int back = net.slot(h ^ 1);
        int nxt = h ^ 1;
        for (int k = 1; k <= deg; ++k) {
          const int g = av.half_edges[(back - k + deg) % deg];
          if (on_loop(g)) {
            nxt = g;
            break;
          }
        }
        double corner = sweep(av.angle[net.slot(nxt)], av.angle[back], av.total);
        if (corner == 0) corner = av.total;
        turning += std::numbers::pi - corner;
        h = nxt;
      }
      cycles.push_back({turning, std::move(cycle)});
    }
  std::sort(cycles.begin(), cycles.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::vector<int>> loops;
  for (auto& c : cycles) loops.push_back(std::move(c.second));
  return loops;
}

// The plane groups of a region's loop stretches and the traces along them,
// each once in loop order.
void credit_groups_and_traces(const TraceNetwork& net, SurfaceRegion& region) {
  const auto& edges = net.edges();
  for (const auto& loop : region.loops)
    for (int h : loop) {
      const int g = edges[h / 2].group;
      if (std::find(region.groups.begin(), region.groups.end(), g) == region.groups.end())
        region.groups.push_back(g);
      // The traces of the discontinuity that run along this stretch (its
      // midpoint on their marked polyline); a stretch that only snapping
      // or extension made is credited to all of them.
      const Eigen::Vector3d mid =
          (net.vertices()[net.origin(h)] + net.vertices()[net.target(h)]) / 2;
      std::vector<int> along;
      for (int t : net.groups()[g].traces)
        if (distance_to_polyline(net.trace_points()[t], mid) <= net.snap_tolerance())
          along.push_back(t);
      if (along.empty()) along = net.groups()[g].traces;
      for (int t : along)
        if (std::find(region.traces.begin(), region.traces.end(), t) == region.traces.end())
          region.traces.push_back(t);
    }
}

}  // namespace

int winding_number(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p) {
  int w = 0;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % n];
    const double side = (b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y());
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && side > 0) ++w;
    } else if (b.y() <= p.y() && side < 0) {
      --w;
    }
  }
  return w;
}

SurfaceLoops SurfaceLoops::find(const TraceNetwork& net, const FreeSurface& surface) {
  SurfaceLoops out;
  const auto& edges = net.edges();
  const size_t nh = 2 * edges.size();
  out.half_edge_face_.assign(nh, -1);

  // --- Faces by Lu's rule ------------------------------------------------------
  out.faces_ = faces_by_lus_rule(net, surface, out.half_edge_face_);

  // --- Regions: faces joined across patch edges that no trace follows ---------
  const size_t nf = out.faces_.size();
  UnionFind uf(nf + 1);
  const int outside = static_cast<int>(nf);
  for (size_t f = 0; f < nf; ++f)
    if (out.faces_[f].patch < 0) uf.unite(static_cast<int>(f), outside);
  for (size_t e = 0; e < edges.size(); ++e)
    if (edges[e].group < 0) uf.unite(out.half_edge_face_[2 * e], out.half_edge_face_[2 * e + 1]);
  // An island's outside (a face of no positive area) is a hole in the face around it.
  zero_the_walks_around_trees(out.faces_, out.half_edge_face_);
  for (size_t f = 0; f < nf; ++f) {
    const SurfaceFace& hole = out.faces_[f];
    if (hole.patch < 0 || hole.area > 0) continue;
    const int around = face_around_island(net, surface, out.faces_, hole);
    uf.unite(static_cast<int>(f), around >= 0 ? around : outside);
  }
  collect_regions(out.faces_, uf, outside, out.face_region_, out.regions_);

  // --- Loops: the trace stretches between a region and its neighbours ---------
  auto region_of_half_edge = [&](int h) { return out.face_region_[out.half_edge_face_[h]]; };
  for (size_t r = 0; r < out.regions_.size(); ++r) {
    SurfaceRegion& region = out.regions_[r];
    auto on_loop = [&](int h) {
      return edges[h / 2].group >= 0 && region_of_half_edge(h) == static_cast<int>(r) &&
             region_of_half_edge(h ^ 1) != static_cast<int>(r);
    };
    region.loops = loops_around_region(net, out.faces_, region, nh, on_loop);
    credit_groups_and_traces(net, region);
  }
  return out;
}

}  // namespace rockface::faces
