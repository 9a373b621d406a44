#pragma once
// Which surface patches a camera ray can hit, binned over the image: the
// renderer casts one ray per pixel, and a tunnel is thousands of patches
// (walls and roof as facets), so testing every patch on every ray would
// cost minutes per image. A planar polygon wholly in front of the camera
// projects inside the bounding box of its projected vertices, so the patches
// whose box covers a cell are the only ones a ray through that cell can
// hit; patches that reach behind the camera are kept in every cell.
// Candidates stay in patch order, so the nearest hit (and its tie-break)
// is the same as testing every patch: the pixels do not change.
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::camera {

class RayPatchBins {
 public:
  // `polygons` in world coordinates; the window [lo, hi] in normalised image
  // coordinates (x / z, y / z in the camera frame) covers the rays asked.
  RayPatchBins(const std::vector<std::vector<Eigen::Vector3d>>& polygons,
               const photogrammetry::CameraPose& pose, const Eigen::Vector2d& lo,
               const Eigen::Vector2d& hi, int cells_per_side = 64);

  // Patch indices (ascending) a ray with these normalised coordinates can
  // hit; nullptr when the ray lies outside the window (test every patch).
  const std::vector<int>* candidates(double x, double y) const;

 private:
  Eigen::Vector2d lo_, hi_, cell_size_;
  int n_ = 0;
  std::vector<std::vector<int>> cells_;
};

}  // namespace rockface::camera
