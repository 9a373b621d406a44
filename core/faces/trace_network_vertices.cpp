// Phases 4 and 5 of TraceNetwork::build: where the stretches cross each
// other and the patch edges, how far a marked end reaches, and the vertices
// that crossings, corners and ends close together become.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "core/faces/tolerances.h"
#include "core/faces/trace_network_phases.h"
#include "core/faces/union_find.h"

namespace rockface::faces::network_phases {

namespace {

// Points to be clustered into vertices; higher rank wins the position.
struct Candidate {
  Eigen::Vector3d x;
  int rank = 0;  // 3 patch corner, 2 on a patch edge, 1 crossing, 0 marked end
};

}  // namespace

std::vector<Hit> crossings_and_extensions(std::vector<Segment>& segments,
                                          const std::vector<std::vector<int>>& by_patch,
                                          const FreeSurface& surface, double tolerance,
                                          double slack) {
  const auto& patches = surface.patches();
  std::vector<Hit> hits;
  for (size_t k = 0; k < patches.size(); ++k) {
    const SurfacePatch& P = patches[k];
    const size_t n = P.polygon2d.size();
    std::vector<int> list;
    for (int i : by_patch[k])
      if (segments[i].alive) list.push_back(i);
    auto reach = [&](const Segment& s, double& lo, double& hi) {
      lo = s.t0 - (s.free0 ? tolerance : slack);
      hi = s.t1 + (s.free1 ? tolerance : slack);
    };
    for (size_t x = 0; x < list.size(); ++x) {
      const Segment& a = segments[list[x]];
      double alo, ahi;
      reach(a, alo, ahi);
      for (size_t y = x + 1; y < list.size(); ++y) {
        const Segment& b = segments[list[y]];
        const double den = cross2(a.u, b.u);
        if (std::abs(den) < kParallelSine) continue;
        const Eigen::Vector2d d = b.p - a.p;
        const double s = cross2(d, b.u) / den, t = cross2(d, a.u) / den;
        double blo, bhi;
        reach(b, blo, bhi);
        if (s < alo || s > ahi || t < blo || t > bhi) continue;
        hits.push_back({static_cast<int>(k), list[x], s, list[y], -1, t, a.at(s)});
      }
      for (size_t e = 0; e < n; ++e) {
        if (static_cast<int>(e) == a.on_edge) continue;
        const Eigen::Vector2d A = P.polygon2d[e], B = P.polygon2d[(e + 1) % n];
        const double len = (B - A).norm();
        const Eigen::Vector2d ue = (B - A) / len;
        const double den = cross2(a.u, ue);
        if (std::abs(den) < kParallelSine) continue;
        const Eigen::Vector2d d = A - a.p;
        const double s = cross2(d, ue) / den, t = cross2(d, a.u) / den;
        if (s < alo || s > ahi || t < -tolerance || t > len + tolerance) continue;
        hits.push_back({static_cast<int>(k), list[x], s, -1, static_cast<int>(e), t, a.at(s)});
      }
    }
  }
  // A marked end reaches only the nearest trace or edge ahead of it.
  {
    std::vector<int> best_lo(segments.size(), -1), best_hi(segments.size(), -1);
    auto consider = [&](int seg, double param, int h) {
      const Segment& s = segments[seg];
      if (param < s.t0 - slack) {
        if (best_lo[seg] < 0 ||
            param > (hits[best_lo[seg]].a == seg ? hits[best_lo[seg]].s : hits[best_lo[seg]].t))
          best_lo[seg] = h;
      } else if (param > s.t1 + slack) {
        if (best_hi[seg] < 0 ||
            param < (hits[best_hi[seg]].a == seg ? hits[best_hi[seg]].s : hits[best_hi[seg]].t))
          best_hi[seg] = h;
      }
    };
    for (size_t h = 0; h < hits.size(); ++h) {
      consider(hits[h].a, hits[h].s, static_cast<int>(h));
      if (hits[h].b >= 0) consider(hits[h].b, hits[h].t, static_cast<int>(h));
    }
    auto ok = [&](int seg, double param, int h) {
      const Segment& s = segments[seg];
      if (param < s.t0 - slack) return best_lo[seg] == h;
      if (param > s.t1 + slack) return best_hi[seg] == h;
      return true;
    };
    for (size_t h = 0; h < hits.size(); ++h) {
      Hit& hit = hits[h];
      hit.kept = ok(hit.a, hit.s, static_cast<int>(h)) &&
                 (hit.b < 0 || ok(hit.b, hit.t, static_cast<int>(h)));
    }
    for (size_t h = 0; h < hits.size(); ++h) {
      const Hit& hit = hits[h];
      if (!hit.kept) continue;
      for (auto [seg, param] : {std::pair{hit.a, hit.s}, std::pair{hit.b, hit.t}}) {
        if (seg < 0) continue;
        Segment& s = segments[seg];
        if (param < s.t0) s.t0 = param, s.free0 = false;
        if (param > s.t1) s.t1 = param, s.free1 = false;
      }
    }
  }
  return hits;
}

Vertices merge_vertices(std::vector<Segment>& segments, const std::vector<Hit>& hits,
                        const FreeSurface& surface, double tolerance, double slack) {
  const auto& patches = surface.patches();
  std::vector<Eigen::Vector3d> points;
  std::vector<Candidate> cands;
  std::vector<std::vector<int>> corner_cand(patches.size());
  for (size_t k = 0; k < patches.size(); ++k)
    for (const auto& c : patches[k].polygon) {
      corner_cand[k].push_back(static_cast<int>(cands.size()));
      cands.push_back({c, 3});
    }
  for (const Hit& hit : hits) {
    if (!hit.kept) continue;
    const int c = static_cast<int>(cands.size());
    cands.push_back({patches[hit.patch].to3d(hit.x), hit.b < 0 ? 2 : 1});
    segments[hit.a].points.push_back({hit.s, c});
    if (hit.b >= 0) segments[hit.b].points.push_back({hit.t, c});
  }
  for (auto& s : segments) {
    if (!s.alive) continue;
    for (double t : {s.t0, s.t1}) {
      bool have = false;
      for (const auto& [param, c] : s.points) have = have || std::abs(param - t) <= slack;
      if (have) continue;
      const bool on_edge = (t == s.t0 ? !s.free0 : !s.free1) || s.on_edge >= 0;
      const int c = static_cast<int>(cands.size());
      cands.push_back({patches[s.patch].to3d(s.at(t)), on_edge ? 2 : 0});
      s.points.push_back({t, c});
    }
  }
  UnionFind cuf(cands.size());
  {
    struct KeyHash {
      size_t operator()(const std::array<long long, 3>& k) const {
        return static_cast<size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
      }
    };
    std::unordered_map<std::array<long long, 3>, std::vector<int>, KeyHash> grid;
    auto key = [&](const Eigen::Vector3d& x) {
      return std::array<long long, 3>{static_cast<long long>(std::floor(x.x() / tolerance)),
                                      static_cast<long long>(std::floor(x.y() / tolerance)),
                                      static_cast<long long>(std::floor(x.z() / tolerance))};
    };
    for (size_t i = 0; i < cands.size(); ++i) grid[key(cands[i].x)].push_back(static_cast<int>(i));
    for (size_t i = 0; i < cands.size(); ++i) {
      const auto k0 = key(cands[i].x);
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz) {
            auto it = grid.find({k0[0] + dx, k0[1] + dy, k0[2] + dz});
            if (it == grid.end()) continue;
            for (int j : it->second)
              if (j > static_cast<int>(i) && (cands[j].x - cands[i].x).norm() <= tolerance)
                cuf.unite(static_cast<int>(i), j);
          }
    }
  }
  std::vector<int> vertex_of(cands.size(), -1);
  {
    std::vector<int> best_rank(cands.size(), -1);
    for (size_t i = 0; i < cands.size(); ++i) {
      const int r = cuf.find(static_cast<int>(i));
      best_rank[r] = std::max(best_rank[r], cands[i].rank);
    }
    std::vector<Eigen::Vector3d> sum(cands.size(), Eigen::Vector3d::Zero());
    std::vector<int> count(cands.size(), 0);
    for (size_t i = 0; i < cands.size(); ++i) {
      const int r = cuf.find(static_cast<int>(i));
      if (cands[i].rank != best_rank[r]) continue;
      sum[r] += cands[i].x;
      ++count[r];
    }
    for (size_t i = 0; i < cands.size(); ++i) {
      const int r = cuf.find(static_cast<int>(i));
      if (vertex_of[r] < 0) {
        vertex_of[r] = static_cast<int>(points.size());
        points.push_back(sum[r] / count[r]);
      }
      vertex_of[i] = vertex_of[r];
    }
  }
  return {std::move(points), std::move(vertex_of)};
}

}  // namespace rockface::faces::network_phases
