#include "ui/view3d/overlay_drape.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

namespace rockface::ui {

namespace {

// Halvings of a piece between two samples before it is taken as it is: a
// sample step of one spacing halved 8 times is far below a triangle, so a
// piece that still spans two triangles that share no edge crosses a vertex
// of the surface (and a straight chord there stays within the vertex's fan).
constexpr int kMaxRefine = 8;

}  // namespace

bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

SurfaceDrape::SurfaceDrape(const DisplayMesh& mesh) {
  const std::size_t n = mesh.positions.size() / 3;
  surface_.vertices.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    surface_.vertices.push_back(mesh.centre + Eigen::Vector3d(mesh.positions[3 * i],
                                                              mesh.positions[3 * i + 1],
                                                              mesh.positions[3 * i + 2]));
  surface_.triangles.reserve(mesh.triangle_count());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    surface_.triangles.push_back({static_cast<int>(mesh.indices[t]),
                                  static_cast<int>(mesh.indices[t + 1]),
                                  static_cast<int>(mesh.indices[t + 2])});
  picker_ = std::make_unique<measure::MeshPicker>(surface_);
  direction_ = mesh.mean_normal.normalized();
  e1_ = direction_.unitOrthogonal();
  e2_ = direction_.cross(e1_);

  // Edges: the median length is the sampling step; an edge of one triangle
  // is on the border of the mapped area (or of a hole in it).
  std::unordered_map<std::uint64_t, int> uses;  // (low vertex, high vertex) packed
  uses.reserve(surface_.triangles.size() * 2);
  std::vector<double> lengths;
  lengths.reserve(surface_.triangles.size() * 3);
  for (const auto& t : surface_.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++uses[(static_cast<std::uint64_t>(std::min(a, b)) << 32) |
             static_cast<std::uint32_t>(std::max(a, b))];
      lengths.push_back((surface_.vertices[a] - surface_.vertices[b]).norm());
    }
  for (const auto& [edge, count] : uses)
    if (count == 1)
      boundary_.push_back({static_cast<int>(edge >> 32), static_cast<int>(edge & 0xFFFFFFFFu)});
  // Sorted: the same mesh gives the same chains of open edges run after run.
  std::sort(boundary_.begin(), boundary_.end());
  if (!lengths.empty()) {
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    spacing_ = lengths[lengths.size() / 2];
  }
  tolerance_ = std::sqrt(3.0) * mesh.cell + 3 * spacing_;
}

std::optional<measure::PickHit> SurfaceDrape::project(const Eigen::Vector3d& point,
                                                      double slack) const {
  if (!point.allFinite() || surface_.triangles.empty()) return std::nullopt;
  // From `tolerance` in front of the point back through it: the first
  // surface within `tolerance` on either side.
  const double reach = tolerance_ + slack;
  const measure::Ray ray{point + direction_ * reach, -direction_};
  auto hit = picker_->pick(ray);
  if (!hit || hit->distance > 2 * reach) return std::nullopt;
  return hit;
}

Eigen::Vector2d SurfaceDrape::to_plane(const Eigen::Vector3d& point) const {
  return {point.dot(e1_), point.dot(e2_)};
}

std::optional<std::array<int, 2>> SurfaceDrape::shared_edge(int a, int b) const {
  const auto& ta = surface_.triangles[a];
  const auto& tb = surface_.triangles[b];
  std::array<int, 2> shared{-1, -1};
  int n = 0;
  for (int u : ta)
    if (std::find(tb.begin(), tb.end(), u) != tb.end() && n < 2) shared[n++] = u;
  if (n != 2) return std::nullopt;
  return shared;
}

void SurfaceDrape::refine(const measure::PickHit& from, const measure::PickHit& to, int depth,
                          double slack, std::vector<std::vector<Eigen::Vector3d>>& runs) const {
  if (from.triangle == to.triangle) {
    runs.back().push_back(to.point);
    return;
  }
  if (const auto edge = shared_edge(from.triangle, to.triangle)) {
    // Where the vertical plane (containing the drape direction) through the
    // two points cuts the shared edge: the polyline's crease on the surface.
    const Eigen::Vector3d& u = surface_.vertices[(*edge)[0]];
    const Eigen::Vector3d& v = surface_.vertices[(*edge)[1]];
    const Eigen::Vector3d m = (to.point - from.point).cross(direction_);
    const double along = m.dot(v - u);
    if (std::abs(along) > 1e-12 * m.norm() * (v - u).norm()) {
      const double s = std::clamp(m.dot(from.point - u) / along, 0.0, 1.0);
      runs.back().push_back(u + s * (v - u));
    }
    runs.back().push_back(to.point);
    return;
  }
  if (depth >= kMaxRefine) {
    runs.back().push_back(to.point);
    return;
  }
  const auto middle = project(0.5 * (from.point + to.point), slack);
  if (!middle) {
    // A hole (or a notch of the border) between the samples: the run ends
    // before it and a new one starts after it.
    runs.emplace_back();
    runs.back().push_back(to.point);
    return;
  }
  refine(from, *middle, depth + 1, slack, runs);
  refine(*middle, to, depth + 1, slack, runs);
}

std::vector<std::vector<Eigen::Vector3d>> SurfaceDrape::drape(
    const std::vector<Eigen::Vector3d>& line, bool closed, double sag) const {
  std::vector<std::vector<Eigen::Vector3d>> runs;
  if (line.empty() || spacing_ <= 0) return runs;
  std::vector<Eigen::Vector3d> path = line;
  if (closed && line.size() > 2) path.push_back(line.front());
  std::optional<measure::PickHit> last;
  double slack = 0;
  auto visit = [&](const Eigen::Vector3d& sample) {
    auto hit = project(sample, slack);
    if (!hit) {
      last.reset();
      return;
    }
    if (!last) {
      runs.emplace_back();
      runs.back().push_back(hit->point);
    } else {
      refine(*last, *hit, 0, slack, runs);
    }
    last = hit;
  };
  visit(path.front());
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector3d a = path[i - 1], b = path[i];
    slack = sag * (b - a).norm();
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing_)));
    // A segment longer than the whole surface is sampled no finer than
    // 4096 steps: its part on the surface then has samples a surface's
    // width / 4096 apart, refined at the triangles' edges as any other.
    const int n = std::min(steps, 4096);
    for (int k = 1; k <= n; ++k) visit(a + (b - a) * (static_cast<double>(k) / n));
  }
  runs.erase(std::remove_if(runs.begin(), runs.end(),
                            [](const std::vector<Eigen::Vector3d>& r) { return r.size() < 2; }),
             runs.end());
  return runs;
}

const DrapeCache::Runs& DrapeCache::runs(const SurfaceDrape& drape,
                                         const std::vector<Eigen::Vector3d>& line, bool closed,
                                         double sag) {
  std::vector<double> key;
  key.reserve(3 * line.size() + 2);
  key.push_back(closed ? 1 : 0);
  key.push_back(sag);
  for (const auto& p : line) key.insert(key.end(), {p.x(), p.y(), p.z()});
  // A pending trace changes with every tap: old entries go when many pile up.
  if (cache_.size() > 512 && !cache_.count(key)) cache_.clear();
  auto [it, made] = cache_.try_emplace(std::move(key));
  if (made) it->second = drape.drape(line, closed, sag);
  return it->second;
}

std::vector<int> SurfaceDrape::triangles_inside(const std::vector<Eigen::Vector2d>& polygon) const {
  std::vector<int> out;
  if (polygon.size() < 3) return out;
  Eigen::Vector2d lo = polygon[0], hi = polygon[0];
  for (const auto& p : polygon) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (std::size_t t = 0; t < surface_.triangles.size(); ++t) {
    const auto& tri = surface_.triangles[t];
    const Eigen::Vector2d c = to_plane(
        (surface_.vertices[tri[0]] + surface_.vertices[tri[1]] + surface_.vertices[tri[2]]) / 3);
    if ((c.array() < lo.array()).any() || (c.array() > hi.array()).any()) continue;
    if (inside_polygon(polygon, c)) out.push_back(static_cast<int>(t));
  }
  return out;
}

std::vector<std::vector<Eigen::Vector3d>> SurfaceDrape::open_edges_inside(
    const std::vector<Eigen::Vector2d>& polygon) const {
  std::vector<std::vector<Eigen::Vector3d>> out;
  if (polygon.size() < 3) return out;
  std::vector<std::array<int, 2>> edges;
  for (const auto& e : boundary_)
    if (inside_polygon(polygon,
                       to_plane(0.5 * (surface_.vertices[e[0]] + surface_.vertices[e[1]]))))
      edges.push_back(e);
  // Chain them: a dashed line keeps its dashes along the chain.
  std::multimap<int, std::size_t> at;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    at.emplace(edges[i][0], i);
    at.emplace(edges[i][1], i);
  }
  std::vector<bool> used(edges.size(), false);
  auto next_from = [&](int vertex) -> std::optional<std::size_t> {
    auto [lo, hi] = at.equal_range(vertex);
    for (auto it = lo; it != hi; ++it)
      if (!used[it->second]) return it->second;
    return std::nullopt;
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    std::vector<int> chain{edges[i][0], edges[i][1]};
    for (int end = 0; end < 2; ++end) {
      while (const auto k = next_from(chain.back())) {
        used[*k] = true;
        chain.push_back(edges[*k][0] == chain.back() ? edges[*k][1] : edges[*k][0]);
      }
      std::reverse(chain.begin(), chain.end());
    }
    std::vector<Eigen::Vector3d> line;
    for (int v : chain) line.push_back(surface_.vertices[v]);
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace rockface::ui
