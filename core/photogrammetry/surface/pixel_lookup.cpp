#include "core/photogrammetry/surface/pixel_lookup.h"

#include <algorithm>
#include <cmath>

namespace rockface::photogrammetry {

namespace {

// Median lattice edge in pixels of the photograph.
double median_pixel_edge(const SurfaceMesh& mesh) {
  std::vector<double> lengths;
  const std::size_t stride = std::max<std::size_t>(1, mesh.triangles.size() / 5000);
  for (std::size_t i = 0; i < mesh.triangles.size(); i += stride) {
    const auto& t = mesh.triangles[i];
    lengths.push_back((mesh.pixels[t[0]] - mesh.pixels[t[1]]).norm());
  }
  if (lengths.empty()) return 1.0;
  auto mid = lengths.begin() + lengths.size() / 2;
  std::nth_element(lengths.begin(), mid, lengths.end());
  return std::max(*mid, 0.5);
}

}  // namespace

PixelLookup::PixelLookup(const SurfaceMesh& mesh)
    : mesh_(&mesh), cell_(1.5 * median_pixel_edge(mesh)) {
  for (const auto& p : mesh.pixels) {
    if (p.x() < 0 || p.y() < 0) continue;
    cols_ = std::max(cols_, static_cast<int>(p.x() / cell_) + 1);
    rows_ = std::max(rows_, static_cast<int>(p.y() / cell_) + 1);
  }
  // Counting sort of the vertices by bucket, in index order within a bucket.
  starts_.assign(static_cast<std::size_t>(cols_) * rows_ + 1, 0);
  auto bucket_of = [&](const Eigen::Vector2f& p) {
    return index(static_cast<int>(p.x() / cell_), static_cast<int>(p.y() / cell_));
  };
  for (const auto& p : mesh.pixels)
    if (p.x() >= 0 && p.y() >= 0) ++starts_[bucket_of(p) + 1];
  for (std::size_t b = 1; b < starts_.size(); ++b) starts_[b] += starts_[b - 1];
  vertices_.resize(static_cast<std::size_t>(starts_.back()));
  std::vector<int> fill(starts_.begin(), starts_.end() - 1);
  for (std::size_t i = 0; i < mesh.pixels.size(); ++i) {
    const auto& p = mesh.pixels[i];
    if (p.x() < 0 || p.y() < 0) continue;
    vertices_[static_cast<std::size_t>(fill[bucket_of(p)]++)] = static_cast<int>(i);
  }
}

int PixelLookup::nearest(const Eigen::Vector2d& pixel) const {
  const int cx = static_cast<int>(std::floor(pixel.x() / cell_));
  const int cy = static_cast<int>(std::floor(pixel.y() / cell_));
  const Eigen::Vector2f p = pixel.cast<float>();
  double best = cell_ * cell_;
  int found = -1;
  for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, rows_ - 1); ++y)
    for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, cols_ - 1); ++x)
      for (int k = starts_[index(x, y)]; k < starts_[index(x, y) + 1]; ++k) {
        const int i = vertices_[static_cast<std::size_t>(k)];
        const double d2 = (mesh_->pixels[i] - p).squaredNorm();
        if (d2 <= best) {
          best = d2;
          found = i;
        }
      }
  return found;
}

}  // namespace rockface::photogrammetry
