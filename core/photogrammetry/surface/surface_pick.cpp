#include "core/photogrammetry/surface/surface_pick.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>
#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/camera_cv.h"

namespace rockface::photogrammetry {

std::optional<Eigen::Vector3d> surface_point_at_pick(const SurfaceMesh& mesh,
                                                     const Eigen::Vector2d& pixel,
                                                     const CameraIntrinsics& left,
                                                     const SurfacePickOptions& options) {
  std::vector<Eigen::Vector3d> near;
  const Eigen::Vector2f p = pixel.cast<float>();
  const double r2 = options.radius_px * options.radius_px;
  for (std::size_t i = 0; i < mesh.pixels.size(); ++i)
    if ((mesh.pixels[i] - p).squaredNorm() <= r2) near.push_back(mesh.vertices[i]);
  if (near.size() < 3) return std::nullopt;
  const Eigen::Vector2d n = undistort_to_normalised({pixel}, left)[0];
  const Eigen::Vector3d ray = Eigen::Vector3d(n.x(), n.y(), 1.0).normalized();

  // Least median of squares: the plane through three vertices whose median
  // distance to all of them is smallest.
  cv::RNG rng(0x5eed);
  const int count = static_cast<int>(near.size());
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_normal = ray, best_point = near.front();
  std::vector<double> distance(near.size());
  for (int t = 0; t < options.trials; ++t) {
    const Eigen::Vector3d& a = near[static_cast<std::size_t>(rng.uniform(0, count))];
    const Eigen::Vector3d& b = near[static_cast<std::size_t>(rng.uniform(0, count))];
    const Eigen::Vector3d& c = near[static_cast<std::size_t>(rng.uniform(0, count))];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-12) continue;
    const Eigen::Vector3d u = normal.normalized();
    for (std::size_t i = 0; i < near.size(); ++i) distance[i] = std::abs((near[i] - a).dot(u));
    auto mid = distance.begin() + static_cast<std::ptrdiff_t>(distance.size() / 2);
    std::nth_element(distance.begin(), mid, distance.end());
    if (*mid < best) {
      best = *mid;
      best_normal = u;
      best_point = a;
    }
  }
  // Least squares over the inliers (1.4826 x the median: the robust sigma).
  const double limit = options.inlier_sigma * 1.4826 * best;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::size_t inliers = 0;
  for (const auto& v : near)
    if (std::abs((v - best_point).dot(best_normal)) <= limit) {
      mean += v;
      ++inliers;
    }
  if (inliers < 3) return mesh.point_at_pixel(pixel, options.radius_px);
  mean /= static_cast<double>(inliers);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& v : near)
    if (std::abs((v - best_point).dot(best_normal)) <= limit)
      scatter += (v - mean) * (v - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  const Eigen::Vector3d normal = eigen.eigenvectors().col(0);
  // A plane seen edge-on (within ~3 deg) gives no depth along the ray.
  if (std::abs(normal.dot(ray)) < 0.05) return mesh.point_at_pixel(pixel, options.radius_px);
  return ray * (mean.dot(normal) / ray.dot(normal));
}

}  // namespace rockface::photogrammetry
