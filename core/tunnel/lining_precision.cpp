#include "core/tunnel/lining_precision.h"

#include <algorithm>
#include <cmath>

#include "core/common/parallel.h"

namespace rockface::tunnel {

std::optional<double> predicted_normal_sigma(const LiningPrecision& precision,
                                             const Eigen::Vector3d& point,
                                             const Eigen::Vector3d& normal) {
  std::optional<double> best;
  for (const StereoPairView& pair : precision.pairs) {
    const Eigen::Vector3d base = pair.right_centre - pair.left_centre;
    const double b = base.norm();
    if (!(b > 0) || !(pair.focal_px > 0)) continue;
    // The rectified pair's depth axis: the left camera's axis made
    // perpendicular to the base (the normal case the formula is for).
    const Eigen::Vector3d along = base / b;
    Eigen::Vector3d axis = pair.optical_axis - pair.optical_axis.dot(along) * along;
    if (axis.norm() < 1e-9) continue;
    axis.normalize();
    const Eigen::Vector3d ray = point - pair.left_centre;
    const double depth = ray.dot(axis), distance = ray.norm();
    if (!(depth > 0)) continue;
    const double cos_incidence = std::abs(normal.dot(ray / distance));
    // The matching's own error along the ray, projected on the normal, and
    // the window's spread on a surface receding along the row
    // (lining_precision.h).
    const double matching =
        pair.disparity_sigma_px * distance * depth * cos_incidence / (pair.focal_px * b);
    const double slant =
        pair.window_px * depth * std::abs(normal.dot(along)) / (std::sqrt(12.0) * pair.focal_px);
    const double sigma = std::hypot(matching, slant);
    if (!(sigma > 0)) continue;  // edge-on and across the base: no figure
    if (!best || sigma < *best) best = sigma;
  }
  return best;
}

std::vector<double> cell_sigmas(const LiningPrecision& precision, const Alignment& alignment,
                                const DesignProfile& profile, std::span<const double> chainage,
                                std::span<const double> s, double fallback) {
  const std::size_t rows = chainage.size(), cols = s.size();
  std::vector<double> out(rows * cols, fallback);
  // The outline's points and normals are the same in every section.
  std::vector<Eigen::Vector2d> uv(cols), n(cols);
  for (std::size_t j = 0; j < cols; ++j) {
    uv[j] = profile.point_at_length(s[j]);
    n[j] = profile.outward_normal_at_length(s[j]);
  }
  parallel_for(rows, [&](std::size_t i) {
    const TunnelFrame f = alignment.frame_at(
        std::clamp(chainage[i], alignment.first_chainage(), alignment.last_chainage()));
    for (std::size_t j = 0; j < cols; ++j) {
      const Eigen::Vector3d point = f.to_local(uv[j].x(), uv[j].y());
      const Eigen::Vector3d normal = n[j].x() * f.right + n[j].y() * f.up;
      if (const auto sigma = predicted_normal_sigma(precision, point, normal))
        out[i * cols + j] = *sigma;
    }
  });
  return out;
}

}  // namespace rockface::tunnel
