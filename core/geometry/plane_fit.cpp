#include "core/geometry/plane_fit.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace rockface::geometry {

double PlaneFit::normal_sigma(double point_sigma) const {
  const double lever = std::sqrt(static_cast<double>(count)) * spread(1);
  return std::atan2(point_sigma, lever);
}

PlaneFit fit_plane(const std::vector<Eigen::Vector3d>& points) {
  PlaneFit fit;
  fit.count = points.size();
  if (points.empty()) return fit;
  for (const auto& p : points) fit.centroid += p;
  fit.centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : points) cov += (p - fit.centroid) * (p - fit.centroid).transpose();
  cov /= static_cast<double>(points.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  for (int i = 0; i < 3; ++i) fit.spread(i) = std::sqrt(std::max(0.0, eig.eigenvalues()(i)));
  Eigen::Vector3d n = eig.eigenvectors().col(0);
  // Upward, and for a vertical plane the sense DESIGN.md fixes (toward the
  // dip direction, which plane_orientation reads from n either way).
  if (n.z() < 0 || (n.z() == 0 && (n.y() < 0 || (n.y() == 0 && n.x() < 0)))) n = -n;
  fit.normal = n.normalized();
  fit.line = eig.eigenvectors().col(2).normalized();
  return fit;
}

}  // namespace rockface::geometry
