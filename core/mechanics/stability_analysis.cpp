#include "core/mechanics/stability_analysis.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

const char* stability_name(StabilityKind k) {
  switch (k) {
    case StabilityKind::Stable:
      return "stable";
    case StabilityKind::Divergence:
      return "divergence";
    case StabilityKind::Flutter:
      return "flutter";
  }
  return "?";
}

RigidMode describe_mode(const Vector6& z, const std::vector<Eigen::Vector3d>& arms) {
  RigidMode m;
  const Eigen::Vector3d u = z.head<3>(), w = z.tail<3>();
  double fastest = 0, slowest = INFINITY;
  for (const auto& r : arms) {
    const double s = (u + w.cross(r)).norm();
    fastest = std::max(fastest, s);
    slowest = std::min(slowest, s);
  }
  if (!(fastest > 0)) return m;
  // A sign that makes the motion comparable between runs: the centroid
  // moves down (or, moving level, the rotation's largest part is positive).
  double sign = 1;
  if (std::abs(u.z()) > 1e-9 * fastest)
    sign = u.z() < 0 ? 1 : -1;
  else {
    Eigen::Index i = 0;
    (u.norm() > 1e-9 * fastest ? u : w).cwiseAbs().maxCoeff(&i);
    sign = (u.norm() > 1e-9 * fastest ? u : w)(i) >= 0 ? 1 : -1;
  }
  m.translation = sign * u / fastest;
  m.rotation = sign * w / fastest;
  m.rotates = slowest < kPivotSpeedRel * fastest;
  return m;
}

StabilityAnalysis stability_analysis(const Matrix6& k, const Matrix6& m, double length) {
  StabilityAnalysis out;
  // Static mode: least singular vector of S K S, S = diag(1, 1, 1, 1/L, 1/L, 1/L).
  Vector6 s;
  s << 1, 1, 1, 1 / length, 1 / length, 1 / length;
  const Matrix6 ks = s.asDiagonal() * k * s.asDiagonal();
  Eigen::JacobiSVD<Matrix6> svd(ks, Eigen::ComputeFullV);
  out.static_mode = s.asDiagonal() * svd.matrixV().col(5);

  // Dynamic: M = L L^T, A = L^-1 K L^-T, K z = mu M z <=> A y = mu y, z = L^-T y.
  const Eigen::LLT<Matrix6> llt(m);
  const Matrix6 l = llt.matrixL();
  const Matrix6 linv = l.inverse();
  const Matrix6 a = linv * k * linv.transpose();
  Eigen::EigenSolver<Matrix6> es(a, true);
  const auto values = es.eigenvalues();
  std::vector<int> order(6);
  for (int i = 0; i < 6; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](int x, int y) { return values(x).real() < values(y).real(); });
  double largest = 0;
  for (int i = 0; i < 6; ++i) {
    out.mu.push_back(values(order[i]));
    largest = std::max(largest, std::abs(values(i)));
  }
  const int critical = order[0];
  const Eigen::Matrix<std::complex<double>, 6, 1> y = es.eigenvectors().col(critical);
  // A complex mode's real part (its shape at one instant).
  Vector6 yr = y.real();
  if (yr.norm() < 1e-12 * y.norm()) yr = y.imag();
  out.dynamic_mode = linv.transpose() * yr;

  const std::complex<double> c = values(critical);
  bool complex_mode = false;
  for (int i = 0; i < 6; ++i)
    if (std::abs(values(i).imag()) > kComplexEigenRel * largest) complex_mode = true;
  out.critical_complex = std::abs(c.imag()) > kComplexEigenRel * largest;
  if (complex_mode)
    out.kind = StabilityKind::Flutter;
  else if (c.real() <= kZeroEigenRel * largest)
    out.kind = StabilityKind::Divergence;
  else
    out.kind = StabilityKind::Stable;
  return out;
}

}  // namespace rockface::mechanics
