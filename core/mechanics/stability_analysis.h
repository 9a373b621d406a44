#pragma once
// Failure modes and the stability of an equilibrium of a rigid block, from
// its tangent stiffness K (6x6, -d unbalance / d(u, theta), not symmetric
// with friction and follower loads) and its mass matrix M.
//   static mode: the null vector of K (its least singular vector, with
//     rotations scaled by the block size so both parts weigh alike);
//   dynamic mode: from the constrained equations of motion M z'' + K z = 0,
//     z = z0 e^{pt}: (K + p^2 M) z = 0, i.e. K z = mu M z with mu = -p^2,
//     reduced with M's Cholesky factor to a standard eigenproblem. The
//     mode of the least real part of mu is the one that grows first.
//   stability: all mu real and positive: stable (p imaginary, bounded
//     oscillation); a complex mu: flutter (p has a positive real part and
//     an imaginary one, an oscillation that grows); a real mu <= 0:
//     divergence (the block moves off monotonically).
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/mechanics/block_equilibrium.h"

namespace rockface::mechanics {

enum class StabilityKind { Stable, Divergence, Flutter };
const char* stability_name(StabilityKind k);

// A rigid-body mode, normalised so that the fastest of the given points
// (vertices, contacts) moves by 1.
struct RigidMode {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // of the centroid
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();     // rad, rotation vector
  bool rotates = false;  // some point moves < kPivotSpeedRel of the fastest: a pivot
};
RigidMode describe_mode(const Vector6& z, const std::vector<Eigen::Vector3d>& arms);

struct StabilityAnalysis {
  StabilityKind kind = StabilityKind::Stable;
  std::vector<std::complex<double>> mu;  // eigenvalues of K z = mu M z, ascending real part
  bool critical_complex = false;         // the least-real-part mu is one of a complex pair
  Vector6 static_mode = Vector6::Zero();
  Vector6 dynamic_mode = Vector6::Zero();
};

// length: the block's size (scales rotations against translations).
StabilityAnalysis stability_analysis(const Matrix6& k, const Matrix6& m, double length);

}  // namespace rockface::mechanics
