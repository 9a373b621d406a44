#include "camera/ray_patch_bins.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockface::camera {

namespace {
// Vertices closer to the camera plane than this (m) count as reaching
// behind it: their projection is unbounded.
constexpr double kInFront = 1e-6;
// Margin of a patch's box in normalised coordinates: rounding in the
// projection is ~1e-15, a pixel of a 24 Mpx image ~1e-4.
constexpr double kBoxMargin = 1e-9;
}  // namespace

RayPatchBins::RayPatchBins(const std::vector<std::vector<Eigen::Vector3d>>& polygons,
                           const photogrammetry::CameraPose& pose, const Eigen::Vector2d& lo,
                           const Eigen::Vector2d& hi, int cells_per_side)
    : lo_(lo), hi_(hi), n_(std::max(1, cells_per_side)) {
  cell_size_ = (hi_ - lo_) / n_;
  cells_.assign(static_cast<std::size_t>(n_) * n_, {});
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    Eigen::Vector2d blo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d bhi = -blo;
    bool behind = false, any_front = false;
    for (const auto& x : polygons[k]) {
      const Eigen::Vector3d c = pose.to_camera(x);
      if (c.z() <= kInFront) {
        behind = true;
        continue;
      }
      any_front = true;
      const Eigen::Vector2d q(c.x() / c.z(), c.y() / c.z());
      blo = blo.cwiseMin(q);
      bhi = bhi.cwiseMax(q);
    }
    if (!any_front) continue;  // wholly behind the camera: no ray with z > 0 reaches it
    int i0 = 0, i1 = n_ - 1, j0 = 0, j1 = n_ - 1;
    if (!behind) {
      blo.array() -= kBoxMargin;
      bhi.array() += kBoxMargin;
      if (bhi.x() < lo_.x() || bhi.y() < lo_.y() || blo.x() > hi_.x() || blo.y() > hi_.y())
        continue;  // outside the window: rays outside it test every patch anyway
      auto cell = [&](double v, double origin, double size) {
        return std::clamp(static_cast<int>(std::floor((v - origin) / size)), 0, n_ - 1);
      };
      i0 = cell(blo.x(), lo_.x(), cell_size_.x());
      i1 = cell(bhi.x(), lo_.x(), cell_size_.x());
      j0 = cell(blo.y(), lo_.y(), cell_size_.y());
      j1 = cell(bhi.y(), lo_.y(), cell_size_.y());
    }
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        cells_[static_cast<std::size_t>(j) * n_ + i].push_back(static_cast<int>(k));
  }
}

const std::vector<int>* RayPatchBins::candidates(double x, double y) const {
  if (!(x >= lo_.x() && y >= lo_.y() && x <= hi_.x() && y <= hi_.y())) return nullptr;
  const int i = std::min(static_cast<int>((x - lo_.x()) / cell_size_.x()), n_ - 1);
  const int j = std::min(static_cast<int>((y - lo_.y()) / cell_size_.y()), n_ - 1);
  return &cells_[static_cast<std::size_t>(j) * n_ + i];
}

}  // namespace rockface::camera
