#include "core/photogrammetry/surface/cloud_noise.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Eigenvalues>

namespace rockface::photogrammetry {

namespace {

// The sums a cell's plane fit needs, about the cell's first point (survey
// coordinates lose their millimetres in squares otherwise).
struct NoiseCellSums {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  int n = 0;
};

constexpr int kNoiseCellMinPoints = 10;

}  // namespace

std::optional<double> cloud_noise_sigma(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<Eigen::Vector2d>& uv, double cell_m) {
  std::unordered_map<std::uint64_t, NoiseCellSums> cells;
  // Every point of a cloud up to a few million; a larger one every k-th
  // (the median over cells needs thousands of cells, not all of them).
  const std::size_t stride = std::max<std::size_t>(1, points.size() / 2'000'000);
  for (std::size_t i = 0; i < points.size() && i < uv.size(); i += stride) {
    const auto cu = static_cast<std::int64_t>(std::floor(uv[i].x() / cell_m));
    const auto cv = static_cast<std::int64_t>(std::floor(uv[i].y() / cell_m));
    const std::uint64_t key =
        (static_cast<std::uint64_t>(cu) << 32) ^ (static_cast<std::uint64_t>(cv) & 0xffffffffu);
    NoiseCellSums& c = cells[key];
    if (c.n == 0) c.origin = points[i];
    const Eigen::Vector3d d = points[i] - c.origin;
    c.sum += d;
    c.outer += d * d.transpose();
    ++c.n;
  }
  std::vector<double> sigmas;
  for (const auto& [key, c] : cells) {
    if (c.n < kNoiseCellMinPoints) continue;
    const Eigen::Vector3d mean = c.sum / c.n;
    const Eigen::Matrix3d cov = c.outer / c.n - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const double least = std::max(0.0, eig.eigenvalues()[0]);  // ascending: the normal's
    sigmas.push_back(std::sqrt(least * c.n / (c.n - 3)));
  }
  if (sigmas.size() < 10) return std::nullopt;
  auto mid = sigmas.begin() + static_cast<std::ptrdiff_t>(sigmas.size() / 2);
  std::nth_element(sigmas.begin(), mid, sigmas.end());
  return *mid;
}

}  // namespace rockface::photogrammetry
