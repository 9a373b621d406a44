#pragma once
// A small mixed linear complementarity problem, solved by an active set
// with Eigen's complete orthogonal decomposition:
//   w = W z + q,
//   unilateral rows: z_i >= 0, w_i >= 0, z_i w_i = 0  (a contact's normal force),
//   bilateral rows:  w_i = 0, z_i free                 (a sticking contact's friction,
//                                                      a contact held closed).
// W need not be symmetric (sliding friction) nor regular: contacts of one
// face are redundant for a rigid block (more points than the three a plane
// needs), and the least-norm solution of the active rows spreads the load
// over them. The motion (w, and M^-1 H^T z) is what the block's equations
// use; among the force distributions that give it the least-norm one is
// taken.
#include <vector>

#include <Eigen/Core>

namespace rockface::mechanics {

struct MixedLcpResult {
  Eigen::VectorXd z, w;
  bool converged = false;
  int iterations = 0;
};

// unilateral[i]: row i is a complementarity row, else an equality.
// force_tol, accel_tol: how far from complementarity the answer may be.
MixedLcpResult solve_mixed_lcp(const Eigen::MatrixXd& w_matrix, const Eigen::VectorXd& q,
                               const std::vector<bool>& unilateral, double force_tol,
                               double accel_tol, int max_iterations);

}  // namespace rockface::mechanics
