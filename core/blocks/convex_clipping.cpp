#include "core/blocks/convex_clipping.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <utility>

#include <Eigen/Geometry>

namespace rockface::blocks {

namespace {

enum class Side { Inside, On, Outside };

ClippedSolid box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  ClippedSolid s;
  for (int k = 0; k < 8; ++k)
    s.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(),
                            k & 4 ? hi.z() : lo.z());
  for (int axis = 0; axis < 3; ++axis)
    for (int high = 0; high < 2; ++high) {
      const int a = 1 << axis, b = 1 << ((axis + 1) % 3), c = 1 << ((axis + 2) % 3);
      const int base = high ? a : 0;
      std::vector<int> loop{base, base + b, base + b + c, base + c};
      Eigen::Vector3d outward = Eigen::Vector3d::Zero();
      outward[axis] = high ? 1 : -1;
      const auto& v = s.vertices;
      if ((v[loop[1]] - v[loop[0]]).cross(v[loop[2]] - v[loop[0]]).dot(outward) < 0)
        std::reverse(loop.begin(), loop.end());
      s.faces.push_back({-1 - (2 * axis + high), loop});
    }
  return s;
}

// Drops the vertices no face uses and renumbers the loops.
void compact(ClippedSolid& s) {
  std::vector<int> index(s.vertices.size(), -1);
  std::vector<Eigen::Vector3d> kept;
  for (auto& f : s.faces)
    for (int& v : f.loop) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(kept.size());
        kept.push_back(s.vertices[v]);
      }
      v = index[v];
    }
  s.vertices = std::move(kept);
}

// One cut: keeps inward . x >= offset. False when the section does not make
// one closed loop (the tolerance met a configuration it cannot decide).
bool cut(ClippedSolid& s, int plane, const Eigen::Vector3d& inward, double offset,
         double on_plane) {
  const int nv = static_cast<int>(s.vertices.size());
  std::vector<double> d(nv);
  std::vector<Side> side(nv);
  bool any_in = false, any_out = false;
  for (int v = 0; v < nv; ++v) {
    d[v] = inward.dot(s.vertices[v]) - offset;
    side[v] = d[v] > on_plane ? Side::Inside : d[v] < -on_plane ? Side::Outside : Side::On;
    any_in = any_in || side[v] == Side::Inside;
    any_out = any_out || side[v] == Side::Outside;
  }
  if (!any_out) return true;  // the plane cuts nothing off
  if (!any_in) {
    s.faces.clear();  // nothing with volume is left
    return true;
  }
  // The cut point of an edge from inside to outside, shared by both faces
  // of the edge. |d_a - d_b| > 2 on_plane, so t is well conditioned.
  std::map<std::pair<int, int>, int> cut_point;
  auto point_on = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto it = cut_point.find(key);
    if (it != cut_point.end()) return it->second;
    const double t = d[a] / (d[a] - d[b]);
    s.vertices.push_back(s.vertices[a] + t * (s.vertices[b] - s.vertices[a]));
    const int id = static_cast<int>(s.vertices.size()) - 1;
    cut_point.emplace(key, id);
    return id;
  };
  auto on_section = [&](int v) { return v >= nv || side[v] == Side::On; };

  std::vector<ClippedFace> faces;
  std::set<std::pair<int, int>> section_edges;  // counter-clockwise seen from outside the cut
  for (const ClippedFace& f : s.faces) {
    std::vector<int> loop;
    const int n = static_cast<int>(f.loop.size());
    for (int k = 0; k < n; ++k) {
      const int a = f.loop[k], b = f.loop[(k + 1) % n];
      if (side[a] != Side::Outside) loop.push_back(a);
      if ((side[a] == Side::Inside && side[b] == Side::Outside) ||
          (side[a] == Side::Outside && side[b] == Side::Inside))
        loop.push_back(point_on(a, b));
    }
    if (loop.size() < 3) continue;  // cut off, or left touching along an edge
    // A face lying on the cutting plane is replaced by the section.
    if (std::all_of(loop.begin(), loop.end(), on_section)) continue;
    const int m = static_cast<int>(loop.size());
    for (int k = 0; k < m; ++k)
      if (on_section(loop[k]) && on_section(loop[(k + 1) % m]))
        section_edges.insert({loop[(k + 1) % m], loop[k]});
    faces.push_back({f.plane, std::move(loop)});
  }
  // An edge met from both sides is one the plane only touches.
  for (auto it = section_edges.begin(); it != section_edges.end();) {
    auto twin = section_edges.find({it->second, it->first});
    if (twin != section_edges.end()) {
      section_edges.erase(twin);
      it = section_edges.erase(it);
    } else {
      ++it;
    }
  }
  std::map<int, int> next;
  for (const auto& [a, b] : section_edges)
    if (!next.emplace(a, b).second) return false;  // the section pinches at a
  if (next.size() < 3) return false;
  std::vector<int> section;
  int v = next.begin()->first;
  do {
    section.push_back(v);
    auto it = next.find(v);
    if (it == next.end() || section.size() > next.size()) return false;
    v = it->second;
  } while (v != section.front());
  if (section.size() != next.size()) return false;  // more than one loop
  faces.push_back({plane, std::move(section)});
  s.faces = std::move(faces);
  compact(s);
  return true;
}

// Every directed edge once, and its opposite in another face: a closed,
// consistently oriented surface.
bool closed(const ClippedSolid& s) {
  std::set<std::pair<int, int>> directed;
  for (const auto& f : s.faces) {
    const int n = static_cast<int>(f.loop.size());
    for (int k = 0; k < n; ++k)
      if (!directed.insert({f.loop[k], f.loop[(k + 1) % n]}).second) return false;
  }
  for (const auto& [a, b] : directed)
    if (!directed.count({b, a})) return false;
  return true;
}

// Vertices closer than `merge` become one at their mean: the short edges
// collapse and a face left with fewer than three corners goes. The solid is
// kept as it was when that leaves a face pinched or the surface open.
ClippedSolid merge_close_vertices(const ClippedSolid& s, double merge) {
  const int nv = static_cast<int>(s.vertices.size());
  std::vector<int> root(nv);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  bool any = false;
  for (int a = 0; a < nv; ++a)
    for (int b = a + 1; b < nv; ++b)
      if ((s.vertices[a] - s.vertices[b]).norm() <= merge) {
        root[find(b)] = find(a);
        any = true;
      }
  if (!any) return s;
  ClippedSolid out;
  out.vertices.assign(nv, Eigen::Vector3d::Zero());
  std::vector<int> count(nv, 0);
  for (int v = 0; v < nv; ++v) {
    out.vertices[find(v)] += s.vertices[v];
    ++count[find(v)];
  }
  for (int v = 0; v < nv; ++v)
    if (count[v] > 0) out.vertices[v] /= count[v];
  for (const auto& f : s.faces) {
    std::vector<int> loop;
    for (int v : f.loop) {
      const int r = find(v);
      if (loop.empty() || loop.back() != r) loop.push_back(r);
    }
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    if (loop.size() < 3) continue;
    std::vector<int> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return s;  // pinched
    out.faces.push_back({f.plane, std::move(loop)});
  }
  compact(out);
  if (out.faces.size() < 4 || !closed(out)) return s;
  return out;
}

}  // namespace

std::optional<ClippedSolid> clip_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                     const std::vector<Eigen::Vector3d>& inward,
                                     const std::vector<double>& offset, double on_plane,
                                     double merge) {
  ClippedSolid s = box(lo, hi);
  for (int i = 0; i < static_cast<int>(inward.size()); ++i) {
    if (!cut(s, i, inward[i], offset[i], on_plane)) return std::nullopt;
    if (s.faces.empty()) return s;
  }
  return merge_close_vertices(s, merge);
}

}  // namespace rockface::blocks
