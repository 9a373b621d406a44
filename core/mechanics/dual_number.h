#pragma once
// Values with their gradient in two variables (Eigen's forward-mode
// automatic differentiation). The staged joint law evaluates its explicit
// update (slip and normal stress of a step -> dilation and strength) on
// these, so that the return mapping's Newton iteration and the law's
// consistent tangent get exact derivatives of the very functions the
// response is made of, not differences of them.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace rockface::mechanics {

using Dual = Eigen::AutoDiffScalar<Eigen::Vector2d>;

// The independent variable `index` (0 or 1) at `value`.
inline Dual dual_variable(double value, int index) {
  return Dual(value, 2, index);
}

}  // namespace rockface::mechanics
