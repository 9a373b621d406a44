#pragma once
// Path following for R(x, p) = 0: x the (scaled) unknowns, p a scalar
// parameter. Two drivers share one Newton corrector:
//   step_parameter: natural-parameter stepping from p0 to a target (the
//     loads applied in increments), halving an increment that fails;
//   continue_path: pseudo-arc-length continuation (Keller): a predictor
//     along the unit tangent of the path in (x, p), a corrector on the
//     hyperplane normal to it, so the path is followed through and up to a
//     limit point where dp/ds changes sign (or the path turns flat, as it
//     does when a perfectly plastic mechanism forms). Step control: grow
//     after an easy step, halve after a failed one; a maximum of p that a
//     step passes is approached by halving until the step is the minimum,
//     so p there is found to about min_step x the path's curvature.
// Both are bounded: max_steps accepted steps, p_max, min_step; when a bound
// stops the path it says which ("no limit point reached"), never loops.
//
// Path-dependent problems (plastic joints) evaluate the residual from
// their committed state; commit() is called for every accepted point only.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/progress.h"

namespace rockface::mechanics {

class ContinuationProblem {
 public:
  virtual ~ContinuationProblem() = default;
  virtual int size() const = 0;
  // Residual (scaled to order one at the problem's load) at unknowns x and
  // parameter p, from the committed state.
  virtual Eigen::VectorXd residual(const Eigen::VectorXd& x, double p) const = 0;
  // dR/dx to use where differences see no stiffness (contacts exactly at
  // zero load before the first step); empty: none.
  virtual Eigen::MatrixXd fallback_jacobian() const { return {}; }
  // The residual and its exact derivatives dR/dx, dR/dp at (x, p), for a
  // problem that has them (false: the corrector takes forward differences,
  // size() + 1 more residuals a Newton iteration, each as noisy as the
  // residual's own return mappings).
  virtual bool residual_and_jacobian(const Eigen::VectorXd& x, double p, Eigen::VectorXd& r,
                                     Eigen::MatrixXd& jx, Eigen::VectorXd& jp) const {
    (void)x, (void)p, (void)r, (void)jx, (void)jp;
    return false;
  }
  virtual void commit(const Eigen::VectorXd& x, double p) = 0;
};

struct ContinuationOptions {
  double step = 0.05;   // initial arc-length step (scaled units)
  double min_step = 0;  // 0: step / 64
  double max_step = 0;  // 0: step x 1e6
  int max_steps = 400;  // accepted steps
  // Forward differences of the residual even where the problem has exact
  // derivatives: the tangent of the earlier versions, for comparison.
  bool difference_jacobian = false;
  double p_max = 20;  // the path stops here: no limit point below it
  // dp/ds below this (scaled) counts as a flat path: a mechanism. The
  // path creeps up to a frictional limit as the joints' shear stresses
  // turn into the final slip direction (over a few elastic displacements):
  // 1e-5 leaves ~1e-5 x (that distance) of lambda, below 1e-4 in practice.
  double flat_slope = 1e-5;
  Progress* progress = nullptr;  // reports and may cancel (throws Cancelled)
  // Called for every accepted point of continue_path with dR/dx there.
  std::function<void(const Eigen::VectorXd& x, double p, const Eigen::MatrixXd& jacobian)>
      on_accept;
};

struct ContinuationPoint {
  Eigen::VectorXd x;
  double p = 0;
  int iterations = 0;
};

enum class ContinuationStop {
  LimitPoint,      // dp/ds <= flat_slope at the minimum step: the first limit point
  TargetReached,   // step_parameter reached its target
  ParameterBound,  // p reached p_max without a limit point
  StepBound,       // max_steps accepted without a limit point
  NoConvergence,   // the corrector failed at the minimum step
};
const char* stop_name(ContinuationStop s);

struct ContinuationResult {
  std::vector<ContinuationPoint> path;  // accepted points, the start first
  ContinuationStop stop = ContinuationStop::StepBound;
  double p_limit = 0;        // largest p on the path (the limit point's for LimitPoint)
  Eigen::MatrixXd jacobian;  // dR/dx at the last accepted point
  Eigen::VectorXd tangent;   // unit (x, p) tangent at the last accepted point
  // Where the corrector's last failed attempt went, from the last accepted
  // point (scaled): the direction in which the problem runs away.
  Eigen::VectorXd runaway;
  int rejected = 0;  // steps halved
  int residual_evaluations = 0;
};

ContinuationResult step_parameter(ContinuationProblem& problem, const Eigen::VectorXd& x0,
                                  double p0, double p_target, const ContinuationOptions& options);

ContinuationResult continue_path(ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0,
                                 const ContinuationOptions& options);

}  // namespace rockface::mechanics
