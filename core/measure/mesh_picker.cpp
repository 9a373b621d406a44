#include "core/measure/mesh_picker.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

// Triangles per leaf: fewer makes the tree deeper, more makes leaves slower;
// 4 is the usual balance for ray casting.
constexpr std::uint32_t kLeafSize = 4;

struct RayF {
  Eigen::Vector3f origin, inverse;
};

// Entry distance of the ray into the box, or +inf when it misses (slab test).
float enter_box(const RayF& r, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, float limit) {
  float t0 = 0, t1 = limit;
  for (int a = 0; a < 3; ++a) {
    float near = (lo[a] - r.origin[a]) * r.inverse[a];
    float far = (hi[a] - r.origin[a]) * r.inverse[a];
    if (near > far) std::swap(near, far);
    // NaN (0 * inf on a slab face) must not shrink the interval.
    t0 = near > t0 ? near : t0;
    t1 = far < t1 ? far : t1;
    if (t0 > t1) return std::numeric_limits<float>::infinity();
  }
  return t0;
}

// Moeller-Trumbore; distance along the ray or nothing.
std::optional<double> hit_triangle(const Ray& ray, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = ray.direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < std::numeric_limits<double>::min()) return std::nullopt;
  const double inv = 1.0 / det;
  const Eigen::Vector3d s = ray.origin - a;
  const double u = s.dot(p) * inv;
  if (u < -kBarycentricSlack || u > 1 + kBarycentricSlack) return std::nullopt;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = ray.direction.dot(q) * inv;
  if (v < -kBarycentricSlack || u + v > 1 + kBarycentricSlack) return std::nullopt;
  const double t = e2.dot(q) * inv;
  if (t <= 0) return std::nullopt;
  return t;
}

}  // namespace

MeshPicker::MeshPicker(const photogrammetry::SurfaceMesh& mesh) : mesh_(mesh) {
  const std::size_t n = mesh.triangles.size();
  order_.resize(n);
  std::vector<Eigen::Vector3f> centres(n);
  for (std::size_t i = 0; i < n; ++i) {
    order_[i] = static_cast<std::uint32_t>(i);
    const auto& t = mesh.triangles[i];
    centres[i] =
        ((mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0).cast<float>();
  }
  nodes_.reserve(2 * n / kLeafSize + 1);
  if (n > 0) build(0, static_cast<std::uint32_t>(n), centres);
}

std::uint32_t MeshPicker::build(std::uint32_t begin, std::uint32_t end,
                                std::vector<Eigen::Vector3f>& centres) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo, clo = lo, chi = -lo;
  for (std::uint32_t i = begin; i < end; ++i) {
    for (int k : mesh_.triangles[order_[i]]) {
      const Eigen::Vector3f v = mesh_.vertices[k].cast<float>();
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    clo = clo.cwiseMin(centres[order_[i]]);
    chi = chi.cwiseMax(centres[order_[i]]);
  }
  // Float rounding of the corners must not cut off a triangle's edge.
  const float pad = 1e-6f * std::max(1.0f, (hi - lo).cwiseAbs().maxCoeff());
  nodes_[index].lo = lo.array() - pad;
  nodes_[index].hi = hi.array() + pad;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  // Median split on the longest axis of the centres: balanced, O(n log n).
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(
      order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
      [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  build(begin, mid, centres);
  const std::uint32_t right = build(mid, end, centres);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

std::optional<PickHit> MeshPicker::pick(const Ray& ray) const {
  if (nodes_.empty()) return std::nullopt;
  RayF rf;
  rf.origin = ray.origin.cast<float>();
  rf.inverse = ray.direction.cast<float>().cwiseInverse();
  double best = std::numeric_limits<double>::infinity();
  int best_triangle = -1;
  // Nearest child first; a subtree is skipped when its box starts beyond the best hit.
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  const float inf = std::numeric_limits<float>::infinity();
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (enter_box(rf, node.lo, node.hi, inf) > best) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const auto& t = mesh_.triangles[order_[i]];
        const auto d =
            hit_triangle(ray, mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]);
        if (d && *d < best) {
          best = *d;
          best_triangle = static_cast<int>(order_[i]);
        }
      }
      continue;
    }
    const std::uint32_t left = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
    const std::uint32_t right = node.first;
    const float dl = enter_box(rf, nodes_[left].lo, nodes_[left].hi, inf);
    const float dr = enter_box(rf, nodes_[right].lo, nodes_[right].hi, inf);
    // Push the farther first so the nearer is searched first.
    if (dl <= dr) {
      if (dr < best) stack[top++] = right;
      if (dl < best) stack[top++] = left;
    } else {
      if (dl < best) stack[top++] = left;
      if (dr < best) stack[top++] = right;
    }
  }
  if (best_triangle < 0) return std::nullopt;
  const auto& t = mesh_.triangles[best_triangle];
  PickHit hit;
  hit.triangle = best_triangle;
  hit.distance = best;
  hit.point = ray.origin + best * ray.direction;
  Eigen::Vector3d n = (mesh_.vertices[t[1]] - mesh_.vertices[t[0]])
                          .cross(mesh_.vertices[t[2]] - mesh_.vertices[t[0]]);
  if (n.dot(ray.direction) > 0) n = -n;
  hit.normal = n.normalized();
  return hit;
}

std::optional<PickHit> MeshPicker::pick(const PhotoView& view, const Eigen::Vector2d& pixel,
                                        const std::string& where) const {
  return pick(ray_through_pixel(view, pixel, where));
}

std::vector<int> MeshPicker::vertices_near(const Eigen::Vector3d& centre, double radius) const {
  std::vector<int> out;
  if (nodes_.empty()) return out;
  const Eigen::Vector3f lo = (centre.array() - radius).cast<float>();
  const Eigen::Vector3f hi = (centre.array() + radius).cast<float>();
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const std::uint32_t k = stack.back();
    stack.pop_back();
    const Node& node = nodes_[k];
    if ((node.lo.array() > hi.array()).any() || (node.hi.array() < lo.array()).any()) continue;
    if (node.count == 0) {
      stack.push_back(k + 1);
      stack.push_back(node.first);
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
      for (int v : mesh_.triangles[order_[i]])
        if ((mesh_.vertices[v] - centre).squaredNorm() <= radius * radius) out.push_back(v);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> MeshPicker::vertices_inside(const PhotoView& view,
                                             const std::vector<Eigen::Vector2d>& polygon) const {
  std::vector<int> out;
  if (polygon.size() < 3) return out;
  std::vector<cv::Point2f> outline;
  Eigen::Vector2d lo = polygon[0], hi = polygon[0];
  for (const auto& p : polygon) {
    outline.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // A vertex is hidden when the surface along its ray is nearer than it by
  // more than a few point spacings (the surface's own roughness).
  const double hidden_slack = 3.0 * mesh_.median_edge_length();
  const std::size_t chunk = 1 << 16;
  for (std::size_t begin = 0; begin < mesh_.vertices.size(); begin += chunk) {
    const std::size_t end = std::min(mesh_.vertices.size(), begin + chunk);
    const std::vector<Eigen::Vector3d> part(
        mesh_.vertices.begin() + static_cast<std::ptrdiff_t>(begin),
        mesh_.vertices.begin() + static_cast<std::ptrdiff_t>(end));
    const auto px = project_to_view(view, part);
    for (std::size_t i = 0; i < px.size(); ++i) {
      const Eigen::Vector2d& p = px[i];
      if (!(p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y())) continue;
      if (cv::pointPolygonTest(outline,
                               cv::Point2f(static_cast<float>(p.x()), static_cast<float>(p.y())),
                               false) < 0)
        continue;
      const Eigen::Vector3d& v = part[i];
      Ray ray{view.pose.centre, (v - view.pose.centre).normalized()};
      const auto hit = pick(ray);
      if (hit && hit->distance < (v - view.pose.centre).norm() - hidden_slack) continue;
      out.push_back(static_cast<int>(begin + i));
    }
  }
  return out;
}

}  // namespace rockface::measure
