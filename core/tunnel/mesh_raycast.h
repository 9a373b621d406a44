#pragma once
// Ray casting against a triangle mesh: a bounding-volume hierarchy (median
// split of triangle centroids, axis-aligned boxes) and Moller-Trumbore
// intersection. Eigen only. Built once per mesh; queries are const and may
// run on several threads.
#include <array>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rockface::tunnel {

struct RayHit {
  double t = 0;  // distance along the (unit) direction
  std::size_t triangle = 0;
};

class MeshRaycaster {
 public:
  // Triangles with an index outside the vertices throw InputError naming
  // "triangles[i]"; degenerate (zero-area) triangles are skipped.
  MeshRaycaster(std::span<const Eigen::Vector3d> vertices,
                std::span<const std::array<int, 3>> triangles);

  // The nearest hit with t in (t_min, t_max] along origin + t * direction
  // (direction unit), or nothing.
  std::optional<RayHit> first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  double t_min, double t_max) const;

  std::size_t triangle_count() const { return tri_.size(); }
  bool empty() const { return tri_.empty(); }

 private:
  struct Node {
    Eigen::Vector3d lo, hi;
    int left = -1, right = -1;  // children, or -1 for a leaf
    int first = 0, count = 0;   // leaf: range in order_
  };
  struct Tri {
    Eigen::Vector3d a, e1, e2;
    std::size_t index = 0;
  };
  int build(int first, int count, int depth);

  std::vector<Tri> tri_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace rockface::tunnel
