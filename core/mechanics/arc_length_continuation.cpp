#include "core/mechanics/arc_length_continuation.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

const char* stop_name(ContinuationStop s) {
  switch (s) {
    case ContinuationStop::LimitPoint:
      return "limit point";
    case ContinuationStop::TargetReached:
      return "target reached";
    case ContinuationStop::ParameterBound:
      return "no limit point reached below the largest load factor";
    case ContinuationStop::StepBound:
      return "no limit point reached within the step budget";
    case ContinuationStop::NoConvergence:
      return "no equilibrium found at the minimum step";
  }
  return "?";
}

namespace {

struct Corrected {
  bool ok = false;
  Eigen::VectorXd x;
  double p = 0;
  int iterations = 0;
  Eigen::MatrixXd jx;  // dR/dx at the solution
  Eigen::VectorXd jp;  // dR/dp at the solution
};

class Corrector {
 public:
  Corrector(ContinuationProblem& problem, bool differences)
      : problem_(problem), differences_(differences) {}
  int evaluations = 0;

  Eigen::VectorXd residual(const Eigen::VectorXd& x, double p) {
    ++evaluations;
    return problem_.residual(x, p);
  }

  // dR/dx and dR/dp at (x, p): the problem's own, which re-evaluates R
  // there, or forward differences around R = residual(x, p).
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::VectorXd& r, Eigen::MatrixXd& jx,
                Eigen::VectorXd& jp) {
    if (!differences_ && problem_.residual_and_jacobian(x, p, r, jx, jp)) {
      ++evaluations;
      return;
    }
    const int n = static_cast<int>(x.size());
    jx.resize(n, n);
    for (int k = 0; k < n; ++k) {
      Eigen::VectorXd xh = x;
      xh(k) += kTangentStepRel;
      jx.col(k) = (residual(xh, p) - r) / kTangentStepRel;
    }
    const double hp = kParameterStepRel * std::max(1.0, std::abs(p));
    jp = (residual(x, p + hp) - r) / hp;
  }

  // Newton on R(x, p) = 0 and normal . ((x, p) - (x0, p0)) = 0. A zero
  // x-part of `normal` with p-part 1 fixes p (natural parameter).
  Corrected solve(const Eigen::VectorXd& x0, double p0, const Eigen::VectorXd& normal,
                  bool allow_fallback) {
    const int n = static_cast<int>(x0.size());
    Corrected c;
    c.x = x0;
    c.p = p0;
    Eigen::VectorXd r = residual(c.x, c.p);
    for (int it = 0; it <= kNewtonIterations; ++it) {
      if (!r.allFinite()) return c;
      jacobian(c.x, c.p, r, c.jx, c.jp);
      const double norm = r.lpNorm<Eigen::Infinity>();
      if (norm < kEquilibriumResidual) {
        c.ok = true;
        c.iterations = it;
        return c;
      }
      if (it == kNewtonIterations) return c;
      Eigen::MatrixXd a(n + 1, n + 1);
      a.topLeftCorner(n, n) = c.jx;
      a.topRightCorner(n, 1) = c.jp;
      a.bottomRows(1) = normal.transpose();
      Eigen::VectorXd rhs(n + 1);
      rhs.head(n) = -r;
      Eigen::VectorXd z(n + 1), z0(n + 1);
      z << c.x, c.p;
      z0 << x0, p0;
      rhs(n) = -normal.dot(z - z0);
      Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
      lu.setThreshold(kSingularPivotRel);
      if (!lu.isInvertible()) {
        const Eigen::MatrixXd fb =
            allow_fallback ? problem_.fallback_jacobian() : Eigen::MatrixXd();
        if (fb.size() == 0) return c;
        a.topLeftCorner(n, n) = fb;
        lu.compute(a);
        if (!lu.isInvertible()) return c;
      }
      const Eigen::VectorXd dz = lu.solve(rhs);
      if (!dz.allFinite()) return c;
      if (dz.head(n).norm() > kMaxNewtonMove * (1.0 + c.x.norm())) {
        c.x += dz.head(n);  // where it runs away to, for the caller to see
        return c;
      }
      // Backtracking: halve the Newton step while it makes the residual worse.
      double alpha = 1;
      Eigen::VectorXd x_new, r_new;
      double p_new = c.p;
      for (int ls = 0; ls < kLineSearchHalvings; ++ls, alpha *= 0.5) {
        x_new = c.x + alpha * dz.head(n);
        p_new = c.p + alpha * dz(n);
        r_new = residual(x_new, p_new);
        if (r_new.allFinite() && r_new.lpNorm<Eigen::Infinity>() < norm) break;
      }
      c.x = x_new;
      c.p = p_new;
      r = r_new;
    }
    return c;
  }

 private:
  ContinuationProblem& problem_;
  bool differences_;
};

// Unit tangent of the path: [Jx Jp; t_prev^T] t = (0, 1), oriented along t_prev.
Eigen::VectorXd path_tangent(const Eigen::MatrixXd& jx, const Eigen::VectorXd& jp,
                             const Eigen::VectorXd& t_prev) {
  const int n = static_cast<int>(jx.rows());
  Eigen::MatrixXd a(n + 1, n + 1);
  a.topLeftCorner(n, n) = jx;
  a.topRightCorner(n, 1) = jp;
  a.bottomRows(1) = t_prev.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1);
  rhs(n) = 1;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
  lu.setThreshold(kSingularPivotRel);
  if (!lu.isInvertible()) return t_prev;
  Eigen::VectorXd t = lu.solve(rhs);
  if (!t.allFinite() || !(t.norm() > 0)) return t_prev;
  t.normalize();
  return t;
}

void report(const ContinuationOptions& o, int accepted) {
  if (o.progress)
    o.progress->step("equilibrium path",
                     std::min(1.0, static_cast<double>(accepted) / std::max(1, o.max_steps)));
}

}  // namespace

ContinuationResult step_parameter(ContinuationProblem& problem, const Eigen::VectorXd& x0,
                                  double p0, double p_target, const ContinuationOptions& options) {
  ContinuationResult out;
  Corrector corrector(problem, options.difference_jacobian);
  const int n = static_cast<int>(x0.size());
  Eigen::VectorXd fixed_p = Eigen::VectorXd::Zero(n + 1);
  fixed_p(n) = 1;
  out.path.push_back({x0, p0, 0});
  Eigen::VectorXd x = x0;
  double p = p0;
  const double span = p_target - p0;
  double dp = span / kLoadIncrements;
  const double min_dp = span / kLoadIncrementsMax;
  int accepted = 0;
  while (p < p_target) {
    if (accepted >= options.max_steps) {
      out.stop = ContinuationStop::StepBound;
      break;
    }
    const double p_try = std::min(p + dp, p_target);
    const Corrected c = corrector.solve(x, p_try, fixed_p, true);
    if (!c.ok) {
      out.runaway = c.x - x;
      ++out.rejected;
      dp *= 0.5;
      if (dp < min_dp) {
        out.stop = ContinuationStop::NoConvergence;
        break;
      }
      continue;
    }
    problem.commit(c.x, c.p);
    out.path.push_back({c.x, c.p, c.iterations});
    out.jacobian = c.jx;
    x = c.x;
    p = c.p;
    ++accepted;
    report(options, accepted);
    if (c.iterations <= 3) dp *= 1.5;
    if (p >= p_target) out.stop = ContinuationStop::TargetReached;
  }
  out.p_limit = p;
  out.residual_evaluations = corrector.evaluations;
  return out;
}

ContinuationResult continue_path(ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0,
                                 const ContinuationOptions& options) {
  ContinuationResult out;
  Corrector corrector(problem, options.difference_jacobian);
  const int n = static_cast<int>(x0.size());
  const double min_step = options.min_step > 0 ? options.min_step : options.step / 64;
  const double max_step = options.max_step > 0 ? options.max_step : options.step * 1e6;
  out.path.push_back({x0, p0, 0});

  // The start: converged by the caller; its tangent from the Jacobian there.
  Eigen::VectorXd t_up = Eigen::VectorXd::Zero(n + 1);
  t_up(n) = 1;
  Corrected here = corrector.solve(x0, p0, t_up, false);
  if (!here.ok) {
    out.stop = ContinuationStop::NoConvergence;
    out.p_limit = p0;
    out.residual_evaluations = corrector.evaluations;
    return out;
  }
  Eigen::VectorXd z(n + 1);
  z << here.x, here.p;
  Eigen::VectorXd t = path_tangent(here.jx, here.jp, t_up);
  out.jacobian = here.jx;
  out.p_limit = here.p;
  double ds = options.step;
  int accepted = 0;
  for (;;) {
    if (z(n) >= options.p_max) {
      out.stop = ContinuationStop::ParameterBound;
      break;
    }
    if (accepted >= options.max_steps) {
      out.stop = ContinuationStop::StepBound;
      break;
    }
    const Eigen::VectorXd z_pred = z + ds * t;
    const Corrected c = corrector.solve(z_pred.head(n), z_pred(n), t, false);
    if (!c.ok) {
      out.runaway = c.x - z.head(n);
      ++out.rejected;
      ds *= 0.5;
      if (ds < min_step) {
        out.stop = ContinuationStop::NoConvergence;
        break;
      }
      continue;
    }
    Eigen::VectorXd zc(n + 1);
    zc << c.x, c.p;
    const Eigen::VectorXd t_new = path_tangent(c.jx, c.jp, t);
    // Past a maximum: approach it by halving. Flat (a mechanism whose
    // lambda no longer grows): that is the limit, however long the step.
    // A corrector that went far from the prediction, or a tangent that
    // turned sharply, may have jumped to another branch: halve too.
    const bool past = c.p < z(n);
    const bool jumped = (zc - z_pred).norm() > kCorrectorReach * ds || t_new.dot(t) < kSharpTurnCos;
    const bool limit = past || t_new(n) <= options.flat_slope;
    if ((past || jumped) && ds > min_step) {
      ++out.rejected;
      ds = std::max(0.5 * ds, min_step);
      continue;
    }
    problem.commit(c.x, c.p);
    out.path.push_back({c.x, c.p, c.iterations});
    z << c.x, c.p;
    const Eigen::VectorXd t_prev_step = t;
    t = t_new;
    out.jacobian = c.jx;
    out.p_limit = std::max(out.p_limit, c.p);
    ++accepted;
    report(options, accepted);
    if (options.on_accept) options.on_accept(c.x, c.p, c.jx);
    if (limit) {
      out.stop = ContinuationStop::LimitPoint;
      break;
    }
    if (c.iterations <= 3 && t_new.dot(t_prev_step) > kSmoothTurnCos)
      ds = std::min(1.5 * ds, max_step);
  }
  out.tangent = t;
  out.residual_evaluations = corrector.evaluations;
  return out;
}

}  // namespace rockface::mechanics
