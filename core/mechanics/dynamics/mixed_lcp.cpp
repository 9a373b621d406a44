#include "core/mechanics/dynamics/mixed_lcp.h"

#include <Eigen/QR>

namespace rockface::mechanics {

MixedLcpResult solve_mixed_lcp(const Eigen::MatrixXd& w_matrix, const Eigen::VectorXd& q,
                               const std::vector<bool>& unilateral, double force_tol,
                               double accel_tol, int max_iterations) {
  const int n = static_cast<int>(q.size());
  MixedLcpResult out;
  out.z = Eigen::VectorXd::Zero(n);
  out.w = q;
  if (n == 0) {
    out.converged = true;
    return out;
  }
  // Start from the rows that must be active: equalities, and contacts the
  // free motion would push into the rock.
  std::vector<bool> active(n);
  for (int i = 0; i < n; ++i) active[i] = !unilateral[i] || q(i) < -accel_tol;
  for (int it = 0; it < max_iterations; ++it) {
    out.iterations = it + 1;
    std::vector<int> rows;
    for (int i = 0; i < n; ++i)
      if (active[i]) rows.push_back(i);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    if (!rows.empty()) {
      const int m = static_cast<int>(rows.size());
      Eigen::MatrixXd a(m, m);
      Eigen::VectorXd b(m);
      for (int r = 0; r < m; ++r) {
        b(r) = -q(rows[r]);
        for (int c = 0; c < m; ++c) a(r, c) = w_matrix(rows[r], rows[c]);
      }
      const Eigen::VectorXd za = a.completeOrthogonalDecomposition().solve(b);
      for (int r = 0; r < m; ++r) z(rows[r]) = za(r);
    }
    // A contact pulling on the block leaves the active set (the most
    // negative first: one change at a time keeps the search from cycling
    // in the usual non-degenerate cases).
    int worst = -1;
    double worst_value = -force_tol;
    for (int i = 0; i < n; ++i)
      if (active[i] && unilateral[i] && z(i) < worst_value) {
        worst = i;
        worst_value = z(i);
      }
    if (worst >= 0) {
      active[worst] = false;
      continue;
    }
    const Eigen::VectorXd w = w_matrix * z + q;
    worst_value = -accel_tol;
    for (int i = 0; i < n; ++i)
      if (!active[i] && w(i) < worst_value) {
        worst = i;
        worst_value = w(i);
      }
    out.z = z;
    out.w = w;
    if (worst >= 0) {
      active[worst] = true;
      continue;
    }
    for (int i = 0; i < n; ++i)
      if (unilateral[i] && out.z(i) < 0) out.z(i) = 0;  // within force_tol of zero
    out.converged = true;
    return out;
  }
  for (int i = 0; i < n; ++i)
    if (unilateral[i] && out.z(i) < 0) out.z(i) = 0;
  return out;
}

}  // namespace rockface::mechanics
