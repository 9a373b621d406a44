#include "core/photogrammetry/surface/surface_mesh.h"

#include <algorithm>
#include <limits>

namespace rockface::photogrammetry {

void SurfaceMesh::transform(double scale, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  for (auto& v : vertices) v = scale * (R * v) + t;
}

std::optional<Eigen::Vector3d> SurfaceMesh::point_at_pixel(const Eigen::Vector2d& pixel,
                                                           double max_distance_px) const {
  double best = max_distance_px * max_distance_px;
  std::optional<Eigen::Vector3d> found;
  const Eigen::Vector2f p = pixel.cast<float>();
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const double d2 = (pixels[i] - p).squaredNorm();
    if (d2 <= best) {
      best = d2;
      found = vertices[i];
    }
  }
  return found;
}

void SurfaceMesh::pixels_from_texcoords(int width, int height) {
  if (texcoords.size() != vertices.size() || width <= 0 || height <= 0) return;
  texture_width = width;
  texture_height = height;
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  // The inverse of core/photogrammetry/estimators/triangulation.cpp:
  // u = (x + 0.5) / W, v = 1 - (y + 0.5) / H.
  pixels.clear();
  pixels.reserve(texcoords.size());
  for (const auto& t : texcoords) pixels.emplace_back(t.x() * w - 0.5f, (1.0f - t.y()) * h - 0.5f);
}

double SurfaceMesh::median_edge_length() const {
  std::vector<double> lengths;
  // A sample of the triangles is plenty for a median.
  const std::size_t stride = std::max<std::size_t>(1, triangles.size() / 20000);
  for (std::size_t i = 0; i < triangles.size(); i += stride) {
    const auto& t = triangles[i];
    lengths.push_back((vertices[t[0]] - vertices[t[1]]).norm());
    lengths.push_back((vertices[t[0]] - vertices[t[2]]).norm());
  }
  if (lengths.empty()) return 0;
  auto mid = lengths.begin() + lengths.size() / 2;
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

}  // namespace rockface::photogrammetry
