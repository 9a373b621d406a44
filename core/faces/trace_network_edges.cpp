// Phases 6 and 7 of TraceNetwork::build: the edges of the map (stretches
// between vertices and patch edges) and the order of the edges around each
// vertex, unfolding the patches that meet there.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/common/error.h"
#include "core/faces/trace_network_phases.h"

namespace rockface::faces::network_phases {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Counter-clockwise angle from a to b in [0, 2 pi).
double ccw_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  double t = std::atan2(cross2(a, b), a.dot(b));
  if (t < 0) t += kTwoPi;
  if (t >= kTwoPi) t = 0;
  return t;
}

// TraceNetwork::target before the network exists: where half-edge h ends.
int target(const std::vector<NetworkEdge>& edges, int h) {
  return h % 2 == 0 ? edges[h / 2].v1 : edges[h / 2].v0;
}

}  // namespace

std::vector<NetworkEdge> network_edges(std::vector<Segment>& segments,
                                       const std::vector<int>& vertex_of,
                                       const std::vector<Eigen::Vector3d>& vertices,
                                       const FreeSurface& surface, double tolerance,
                                       const std::vector<PlaneGroup>& groups,
                                       std::vector<std::string>& notes) {
  const auto& patches = surface.patches();
  std::vector<NetworkEdge> edges;
  std::map<std::pair<int, int>, int> edge_of;
  auto add_edge = [&](int a, int b, int patch, bool boundary, int group) {
    if (a == b) return;
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    auto it = edge_of.find(key);
    int e;
    if (it == edge_of.end()) {
      e = static_cast<int>(edges.size());
      edge_of[key] = e;
      NetworkEdge ne;
      ne.v0 = key.first;
      ne.v1 = key.second;
      edges.push_back(ne);
    } else {
      e = it->second;
    }
    NetworkEdge& ne = edges[e];
    const bool forward = a == ne.v0;
    bool found = false;
    for (auto& op : ne.patches)
      if (op.patch == patch) {
        found = true;
        if (boundary && !op.boundary) {
          op.boundary = true;
          op.forward = forward;
        }
      }
    if (!found) {
      for (const auto& op : ne.patches)
        if (boundary && op.boundary && op.forward == forward)
          throw InputError(surface.where(patch),
                           "runs along its edge shared with " + surface.where(op.patch) +
                               " in the same direction: list every patch counter-clockwise "
                               "seen from the open side");
      ne.patches.push_back({patch, boundary, forward});
    }
    if (group >= 0) {
      if (ne.group >= 0 && ne.group != group)
        notes.push_back("traces " + groups[ne.group].name + " and " + groups[group].name +
                        " run along the same stretch; it keeps the plane of " +
                        groups[ne.group].name);
      else
        ne.group = group;
    }
  };
  for (auto& s : segments) {
    if (!s.alive) continue;
    std::sort(s.points.begin(), s.points.end());
    for (size_t i = 0; i + 1 < s.points.size(); ++i)
      add_edge(vertex_of[s.points[i].second], vertex_of[s.points[i + 1].second], s.patch,
               s.on_edge >= 0, s.group);
  }
  for (size_t k = 0; k < patches.size(); ++k) {
    const SurfacePatch& P = patches[k];
    const size_t n = P.polygon.size();
    for (size_t e = 0; e < n; ++e) {
      const Eigen::Vector3d A = P.polygon[e], B = P.polygon[(e + 1) % n];
      std::vector<std::pair<double, int>> on;
      for (size_t v = 0; v < vertices.size(); ++v) {
        double param = 0;
        if (distance_to_segment(vertices[v], A, B, param) <= tolerance)
          on.push_back({param, static_cast<int>(v)});
      }
      std::sort(on.begin(), on.end());
      for (size_t i = 0; i + 1 < on.size(); ++i)
        add_edge(on[i].second, on[i + 1].second, static_cast<int>(k), true, -1);
    }
  }
  return edges;
}

VertexOrder order_around_vertices(const std::vector<Eigen::Vector3d>& vertices,
                                  const std::vector<NetworkEdge>& edges,
                                  const FreeSurface& surface) {
  const auto& patches = surface.patches();
  VertexOrder ordered;
  const size_t nv = vertices.size();
  std::vector<std::vector<int>> incident(nv);
  for (size_t e = 0; e < edges.size(); ++e) {
    incident[edges[e].v0].push_back(static_cast<int>(2 * e));
    incident[edges[e].v1].push_back(static_cast<int>(2 * e + 1));
  }
  ordered.around.resize(nv);
  ordered.slot.assign(2 * edges.size(), -1);
  for (size_t v = 0; v < nv; ++v) {
    struct PatchAt {
      int patch = -1;
      int start = -1, end = -1;  // outgoing half-edges along the patch boundary
      Eigen::Vector2d start_dir = Eigen::Vector2d::UnitX();
      double sector = kTwoPi, offset = 0;
      int next = -1;
      bool has_prev = false;
    };
    std::vector<PatchAt> at;
    auto find_at = [&](int patch) -> PatchAt& {
      for (auto& a : at)
        if (a.patch == patch) return a;
      at.push_back({});
      at.back().patch = patch;
      return at.back();
    };
    auto dir2 = [&](int h, int patch) {
      const SurfacePatch& P = patches[patch];
      return P.dir2d(vertices[target(edges, h)] - vertices[v]).normalized().eval();
    };
    for (int h : incident[v]) {
      const NetworkEdge& e = edges[h / 2];
      const bool out_forward = (h % 2 == 0);  // h runs v0 -> v1
      for (const auto& op : e.patches) {
        PatchAt& a = find_at(op.patch);
        if (!op.boundary) continue;
        // The patch's counter-clockwise boundary leaves v along h when they agree.
        if (op.forward == out_forward)
          a.start = h;
        else
          a.end = h;
      }
    }
    for (auto& a : at) {
      if (a.start >= 0 && a.end >= 0) {
        a.start_dir = dir2(a.start, a.patch);
        a.sector = ccw_angle(a.start_dir, dir2(a.end, a.patch));
        if (a.sector <= 0) a.sector = kTwoPi;
      } else {
        a.start = a.end = -1;
        for (int h : incident[v]) {
          bool on = false;
          for (const auto& op : edges[h / 2].patches) on = on || op.patch == a.patch;
          if (on) {
            a.start_dir = dir2(h, a.patch);
            break;
          }
        }
      }
    }
    for (size_t i = 0; i < at.size(); ++i)
      for (size_t j = 0; j < at.size(); ++j)
        if (i != j && at[i].end >= 0 && at[i].end == at[j].start) {
          at[i].next = static_cast<int>(j);
          at[j].has_prev = true;
        }
    double sum = 0;
    int open = 0;
    for (const auto& a : at) {
      sum += a.sector;
      // A patch around an inner vertex covers the full turn: nothing is open there.
      open += (a.has_prev || a.start < 0) ? 0 : 1;
    }
    const double gap = open > 0 ? std::max((kTwoPi - sum) / open, std::numbers::pi / 4) : 0;
    AroundVertex& av = ordered.around[v];
    std::vector<bool> placed(at.size(), false);
    double cursor = 0;
    auto run_chain = [&](int first) {
      for (int i = first; i >= 0 && !placed[i]; i = at[i].next) {
        placed[i] = true;
        at[i].offset = cursor;
        av.sectors.push_back({at[i].patch, cursor, cursor + at[i].sector});
        cursor += at[i].sector;
      }
    };
    for (size_t i = 0; i < at.size(); ++i)
      if (!at[i].has_prev && at[i].start >= 0) {
        run_chain(static_cast<int>(i));
        cursor += gap;
      }
    for (size_t i = 0; i < at.size(); ++i)
      if (!placed[i]) run_chain(static_cast<int>(i));
    av.total = cursor;
    std::vector<std::pair<double, int>> order;
    for (int h : incident[v]) {
      double pos = -1;
      for (const auto& op : edges[h / 2].patches) {
        const PatchAt& a = find_at(op.patch);
        if (h == a.start)
          pos = a.offset;
        else if (h == a.end)
          pos = a.offset + a.sector;
        else
          pos = a.offset + std::min(ccw_angle(a.start_dir, dir2(h, op.patch)), a.sector);
        if (op.boundary) break;  // a boundary position is exact; prefer it
      }
      order.push_back({pos, h});
    }
    std::sort(order.begin(), order.end());
    for (size_t i = 0; i < order.size(); ++i) {
      av.half_edges.push_back(order[i].second);
      av.angle.push_back(order[i].first);
      ordered.slot[order[i].second] = static_cast<int>(i);
    }
  }
  return ordered;
}

}  // namespace rockface::faces::network_phases
