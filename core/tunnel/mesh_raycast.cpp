#include "core/tunnel/mesh_raycast.h"

#include <algorithm>
#include <limits>

#include "core/common/error.h"
#include "core/tunnel/tolerances.h"

namespace rockface::tunnel {

namespace {
constexpr int kLeafSize = 4;
}

MeshRaycaster::MeshRaycaster(std::span<const Eigen::Vector3d> vertices,
                             std::span<const std::array<int, 3>> triangles) {
  const auto nv = static_cast<long long>(vertices.size());
  tri_.reserve(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    for (int k : t)
      if (k < 0 || k >= nv)
        throw InputError("triangles[" + std::to_string(i) + "]",
                         "vertex index " + std::to_string(k) + " outside the " +
                             std::to_string(nv) + " vertices");
    Tri tri;
    tri.a = vertices[static_cast<std::size_t>(t[0])];
    tri.e1 = vertices[static_cast<std::size_t>(t[1])] - tri.a;
    tri.e2 = vertices[static_cast<std::size_t>(t[2])] - tri.a;
    tri.index = i;
    if (!tri.a.allFinite() || !tri.e1.allFinite() || !tri.e2.allFinite())
      throw InputError("triangles[" + std::to_string(i) + "]", "a vertex is not finite");
    if (tri.e1.cross(tri.e2).squaredNorm() == 0) continue;  // no area: nothing to hit
    tri_.push_back(tri);
  }
  order_.resize(tri_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
  if (!tri_.empty()) {
    nodes_.reserve(2 * tri_.size() / kLeafSize + 2);
    build(0, static_cast<int>(tri_.size()), 0);
  }
}

int MeshRaycaster::build(int first, int count, int depth) {
  Node node;
  node.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  node.hi = -node.lo;
  Eigen::Vector3d clo = node.lo, chi = node.hi;  // of the centroids
  for (int k = first; k < first + count; ++k) {
    const Tri& t = tri_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])];
    for (const Eigen::Vector3d& p :
         {t.a, Eigen::Vector3d(t.a + t.e1), Eigen::Vector3d(t.a + t.e2)}) {
      node.lo = node.lo.cwiseMin(p);
      node.hi = node.hi.cwiseMax(p);
    }
    const Eigen::Vector3d c = t.a + (t.e1 + t.e2) / 3;
    clo = clo.cwiseMin(c);
    chi = chi.cwiseMax(c);
  }
  // Pad the box: a ray through a vertex or along an edge on the box's
  // boundary must not be lost to the rounding of the slab test.
  const double pad = kBarycentricSlack *
                     std::max(1.0, (node.hi - node.lo).maxCoeff() + node.lo.cwiseAbs().maxCoeff());
  node.lo.array() -= pad;
  node.hi.array() += pad;
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (count <= kLeafSize || depth > 60) {
    nodes_[static_cast<std::size_t>(id)].first = first;
    nodes_[static_cast<std::size_t>(id)].count = count;
    return id;
  }
  int axis;
  (chi - clo).maxCoeff(&axis);
  const int mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](int a, int b) {
                     const Tri& ta = tri_[static_cast<std::size_t>(a)];
                     const Tri& tb = tri_[static_cast<std::size_t>(b)];
                     return (3 * ta.a + ta.e1 + ta.e2)[axis] < (3 * tb.a + tb.e1 + tb.e2)[axis];
                   });
  const int left = build(first, mid - first, depth + 1);
  const int right = build(mid, first + count - mid, depth + 1);
  nodes_[static_cast<std::size_t>(id)].left = left;
  nodes_[static_cast<std::size_t>(id)].right = right;
  return id;
}

std::optional<RayHit> MeshRaycaster::first_hit(const Eigen::Vector3d& origin,
                                               const Eigen::Vector3d& direction, double t_min,
                                               double t_max) const {
  if (nodes_.empty()) return std::nullopt;
  const Eigen::Vector3d inv = direction.cwiseInverse();  // +-inf on zero components: IEEE slabs
  auto box_entry = [&](const Node& n, double limit) {
    double lo = t_min, hi = limit;
    for (int k = 0; k < 3; ++k) {
      double a = (n.lo[k] - origin[k]) * inv[k], b = (n.hi[k] - origin[k]) * inv[k];
      if (a > b) std::swap(a, b);
      if (std::isnan(a) || std::isnan(b)) {  // 0 * inf: origin on the slab plane, parallel ray
        if (origin[k] < n.lo[k] || origin[k] > n.hi[k])
          return std::numeric_limits<double>::infinity();
        continue;
      }
      lo = std::max(lo, a);
      hi = std::min(hi, b);
      if (lo > hi) return std::numeric_limits<double>::infinity();
    }
    return lo;
  };
  std::optional<RayHit> best;
  double limit = t_max;
  int stack[128];
  int top = 0;
  if (box_entry(nodes_[0], limit) <= limit) stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[static_cast<std::size_t>(stack[--top])];
    if (n.left < 0) {
      for (int k = n.first; k < n.first + n.count; ++k) {
        const Tri& t = tri_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])];
        // Moller-Trumbore.
        const Eigen::Vector3d p = direction.cross(t.e2);
        const double det = t.e1.dot(p);
        const double scale = t.e1.norm() * t.e2.norm();
        if (std::abs(det) <= kRayParallel * scale) continue;
        const double inv_det = 1 / det;
        const Eigen::Vector3d s = origin - t.a;
        const double u = s.dot(p) * inv_det;
        if (u < -kBarycentricSlack || u > 1 + kBarycentricSlack) continue;
        const Eigen::Vector3d q = s.cross(t.e1);
        const double v = direction.dot(q) * inv_det;
        if (v < -kBarycentricSlack || u + v > 1 + kBarycentricSlack) continue;
        const double dist = t.e2.dot(q) * inv_det;
        if (dist > t_min && dist <= limit) {
          limit = dist;
          best = RayHit{dist, t.index};
        }
      }
      continue;
    }
    const Node& l = nodes_[static_cast<std::size_t>(n.left)];
    const Node& r = nodes_[static_cast<std::size_t>(n.right)];
    const double tl = box_entry(l, limit), tr = box_entry(r, limit);
    // Nearer child last on the stack, so it is searched first.
    if (tl <= tr) {
      if (tr <= limit && top < 128) stack[top++] = n.right;
      if (tl <= limit && top < 128) stack[top++] = n.left;
    } else {
      if (tl <= limit && top < 128) stack[top++] = n.left;
      if (tr <= limit && top < 128) stack[top++] = n.right;
    }
  }
  return best;
}

}  // namespace rockface::tunnel
