#pragma once
// Picking on a 3D image through its photograph: the lattice vertex nearest to
// a pixel, in constant time (a grid of buckets one pick radius wide; the
// lattice is nearly regular in pixels). SurfaceMesh::point_at_pixel does the
// same by a linear scan, which is fine for a handful of picks but not for
// thousands of tie points or the pixels of many traces.
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::photogrammetry {

class PixelLookup {
 public:
  // Keeps a reference to `mesh`. The pick radius is 1.5 lattice cells (in
  // pixels of the photograph): a pixel between vertices finds one, a pixel
  // off the reconstructed surface finds none.
  explicit PixelLookup(const SurfaceMesh& mesh);

  // Vertex index, or -1 when no vertex lies within the radius.
  int nearest(const Eigen::Vector2d& pixel) const;
  double radius_px() const { return cell_; }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * cols_ + x; }
  const SurfaceMesh* mesh_;
  double cell_ = 1;
  int cols_ = 0, rows_ = 0;
  // The vertices by bucket, flat: bucket b holds vertices_[starts_[b] ..
  // starts_[b + 1]) (one allocation, not one per bucket: a 1 Mpx lattice has
  // ~0.4 M buckets, and making and freeing them was most of the lookup's cost).
  std::vector<int> starts_, vertices_;
};

}  // namespace rockface::photogrammetry
