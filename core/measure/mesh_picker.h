#pragma once
// Picking on the 3D image: the first triangle of the mesh along a ray (from
// a pixel of either photograph or of a rendered view), with the point, the
// triangle and its normal. A bounding-volume hierarchy over the triangles
// makes a pick a few microseconds on a 24 Mpx model (tools/bench,
// docs/accuracy-cost.md), fast enough for a finger on a tablet.
//
// Why our own BVH: Eigen's unsupported KdBVH keeps a double box per object
// (~80 MB more for a 3.4 M-triangle model) and has no nearest-first ray
// traversal; OpenCV has no triangle index.
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/measure/photo_view.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

struct PickHit {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  // Unit normal of the triangle hit, turned toward the ray's origin (out of
  // the rock, toward the viewer).
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  int triangle = -1;
  double distance = 0;  // along the ray
};

class MeshPicker {
 public:
  // Builds the index. The mesh must outlive the picker and not change.
  explicit MeshPicker(const photogrammetry::SurfaceMesh& mesh);

  // The nearest hit along the ray, or nothing (no surface there).
  std::optional<PickHit> pick(const Ray& ray) const;
  // Through a pixel of a view; throws InputError(where, ...) for a pixel
  // outside the image or not finite.
  std::optional<PickHit> pick(const PhotoView& view, const Eigen::Vector2d& pixel,
                              const std::string& where) const;

  // Indices of the vertices within `radius` of `centre`.
  std::vector<int> vertices_near(const Eigen::Vector3d& centre, double radius) const;

  // Indices of the vertices the view sees inside a polygon of its pixels
  // (projected inside, and not hidden behind other parts of the surface).
  std::vector<int> vertices_inside(const PhotoView& view,
                                   const std::vector<Eigen::Vector2d>& polygon) const;

  const photogrammetry::SurfaceMesh& mesh() const { return mesh_; }
  std::size_t node_count() const { return nodes_.size(); }

 private:
  struct Node {
    Eigen::Vector3f lo, hi;   // bounds
    std::uint32_t first = 0;  // leaf: first index into order_; inner: right child
    std::uint32_t count = 0;  // leaf: number of triangles; 0 for an inner node
  };
  const photogrammetry::SurfaceMesh& mesh_;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;  // triangle indices, grouped by leaf
  std::uint32_t build(std::uint32_t begin, std::uint32_t end,
                      std::vector<Eigen::Vector3f>& centres);
};

}  // namespace rockface::measure
