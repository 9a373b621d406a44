#include "core/mechanics/equilibrium_path.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/common/error.h"
#include "core/mechanics/arc_length_continuation.h"
#include "core/mechanics/block_equilibrium.h"
#include "core/mechanics/block_loads.h"
#include "core/mechanics/contact_points.h"
#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

const char* outcome_name(PathOutcome o) {
  switch (o) {
    case PathOutcome::LimitPoint:
      return "limit point";
    case PathOutcome::FailsUnderLoads:
      return "fails under its loads";
    case PathOutcome::NoLimitPoint:
      return "no limit point reached";
    case PathOutcome::StepBudget:
      return "no limit point within the step budget";
  }
  return "?";
}

MechanicsOptions mechanics_options(Preset preset) {
  MechanicsOptions o;
  switch (preset) {
    case Preset::fast:
      o.contact_density = 2;
      o.step = 0.1;
      break;
    case Preset::standard:
      o.contact_density = 3;
      o.step = 0.05;
      break;
    case Preset::precise:
      o.contact_density = 6;
      o.step = 0.02;
      break;
  }
  return o;
}

namespace {

// The block's equilibrium in scaled unknowns: translation / d, rotation x
// L / d (d the elastic displacement of the block on its joints under its
// load, L its size), residual force / W and moment / (W L), so that every
// entry of the Jacobian is of order one whatever the joints' stiffness.
class PathProblem final : public ContinuationProblem {
 public:
  PathProblem(BlockEquilibrium& eq, bool loading, double divisor)
      : eq_(eq), loading_(loading), divisor_(divisor) {
    const double d = eq.displacement_scale(), l = eq.length(), w = eq.load_scale();
    dx_ << d, d, d, d / l, d / l, d / l;
    dr_ << w, w, w, w * l, w * l, w * l;
  }
  int size() const override { return 6; }
  Vector6 motion(const Eigen::VectorXd& x) const { return dx_.asDiagonal() * Vector6(x); }
  Eigen::VectorXd residual(const Eigen::VectorXd& x, double p) const override {
    return dr_.cwiseInverse().asDiagonal() *
           eq_.unbalance(motion(x), loading_ ? p : 1.0, loading_ ? divisor_ : p);
  }
  bool residual_and_jacobian(const Eigen::VectorXd& x, double p, Eigen::VectorXd& r,
                             Eigen::MatrixXd& jx, Eigen::VectorXd& jp) const override {
    UnbalanceDerivatives d;
    const Vector6 unbalance =
        eq_.unbalance(motion(x), loading_ ? p : 1.0, loading_ ? divisor_ : p, nullptr, &d);
    const Vector6 inv = dr_.cwiseInverse();
    r = inv.asDiagonal() * unbalance;
    jx = inv.asDiagonal() * d.motion * dx_.asDiagonal();
    jp = inv.asDiagonal() * (loading_ ? d.load_factor : d.divisor);
    return true;
  }
  Eigen::MatrixXd fallback_jacobian() const override {
    return -(dr_.cwiseInverse().asDiagonal() * eq_.elastic_stiffness() * dx_.asDiagonal());
  }
  void commit(const Eigen::VectorXd& x, double p) override {
    eq_.commit(motion(x), loading_ ? p : 1.0, loading_ ? divisor_ : p);
  }
  // Physical tangent stiffness K = -d unbalance / d(u, theta) from the scaled Jacobian.
  Matrix6 stiffness(const Eigen::MatrixXd& jacobian) const {
    return -(dr_.asDiagonal() * Matrix6(jacobian) * dx_.cwiseInverse().asDiagonal());
  }

 private:
  BlockEquilibrium& eq_;
  bool loading_;
  double divisor_;
  Vector6 dx_, dr_;
};

std::vector<Eigen::Vector3d> mode_points(const BlockEquilibrium& eq) {
  // Vertices and contact points: a pivot or a centre of rotation on a
  // joint face shows at the contacts near it.
  std::vector<Eigen::Vector3d> pts = eq.vertex_arms();
  for (const ContactPoint& c : eq.contacts()) pts.push_back(c.position - eq.centroid());
  return pts;
}

PathPoint path_point(const BlockEquilibrium& eq, const Vector6& x, double lambda) {
  PathPoint p;
  p.lambda = lambda;
  p.translation = x.head<3>();
  p.rotation = x.tail<3>();
  const Eigen::Quaterniond q = rotation_quaternion(p.rotation);
  for (const auto& r : eq.vertex_arms())
    p.displacement = std::max(p.displacement, (p.translation + rotation_offset(q, r)).norm());
  return p;
}

}  // namespace

EquilibriumPath equilibrium_path(const blocks::Polyhedron& block,
                                 const blocks::MassProperties& mass,
                                 const kinematics::Effects& effects,
                                 const std::vector<std::shared_ptr<const JointLaw>>& plane_laws,
                                 const std::optional<Eigen::Matrix3d>& insitu_stress,
                                 const MechanicsOptions& options) {
  if (!(options.step > 0) || !std::isfinite(options.step))
    throw InputError("analysis.continuation_step", "must be a positive number");
  if (!(options.lambda_start > 0) || !(options.lambda_max > options.lambda_start))
    throw InputError("analysis.lambda_max", "must exceed the starting load factor");
  if (options.max_steps < 1) throw InputError("analysis.max_steps", "must be at least 1");
  EquilibriumPath out;
  BlockLoads loads = block_loads(block, mass, effects);
  out.effects_used = loads.effects_used;
  out.notes = loads.notes;
  std::vector<ContactPoint> contacts = contact_points(block, options.contact_density);
  out.contacts = static_cast<int>(contacts.size());
  if (insitu_stress && !contacts.empty()) out.effects_used.push_back("insitu_stress");
  BlockEquilibrium eq(block, mass, std::move(contacts), plane_laws, std::move(loads),
                      insitu_stress);
  const Matrix6 m = eq.mass_matrix();
  const std::vector<Eigen::Vector3d> points = mode_points(eq);

  ContinuationOptions co;
  co.step = options.step;
  co.max_steps = options.max_steps;
  co.p_max = options.lambda_max;
  co.progress = options.progress;
  co.difference_jacobian = options.difference_tangent;
  // Steps of at most kPathSlipFraction of the joints' slip scale: the
  // staged laws' history is integrated step by step (none for Coulomb).
  if (eq.slip_scale() > 0)
    co.max_step =
        std::max(kPathSlipFraction * eq.slip_scale() / eq.displacement_scale(), options.step);

  // 1. Loading at strengths x 1 / lambda_start.
  PathProblem loading(eq, true, options.lambda_start);
  const ContinuationResult load = step_parameter(loading, Eigen::VectorXd::Zero(6), 0.0, 1.0, co);
  out.residual_evaluations += load.residual_evaluations;
  out.rejected_steps += load.rejected;
  const Vector6 x_loaded = loading.motion(load.path.back().x);
  if (load.stop != ContinuationStop::TargetReached) {
    out.outcome = PathOutcome::FailsUnderLoads;
    std::ostringstream note;
    note << "no equilibrium under " << load.path.back().p * 100
         << " % of the loads even with the joints' strengths x " << 1 / options.lambda_start
         << ": the block falls or topples whatever its joints' strength";
    out.notes.push_back(note.str());
    // The mode in which it goes: where Newton's iterates ran away to from
    // the last equilibrium (no tangent is singular there: it has none).
    if (load.runaway.size() == 6) {
      const Vector6 z = loading.motion(load.runaway);
      out.static_mode = out.dynamic_mode = describe_mode(z, points);
    }
    out.stability = StabilityKind::Divergence;
    out.path.push_back(path_point(eq, x_loaded, options.lambda_start));
    return out;
  }

  // 2. Strength reduction by arc-length continuation.
  PathProblem reduction(eq, false, 0.0);
  Eigen::VectorXd x0 = load.path.back().x;
  // Flutter is invisible to the static path: every accepted point is checked.
  co.on_accept = [&](const Eigen::VectorXd&, double p, const Eigen::MatrixXd& jx) {
    if (out.flutter_lambda) return;
    if (stability_analysis(reduction.stiffness(jx), m, eq.length()).kind == StabilityKind::Flutter)
      out.flutter_lambda = p;
  };
  const ContinuationResult path = continue_path(reduction, x0, options.lambda_start, co);
  out.residual_evaluations += path.residual_evaluations;
  out.rejected_steps += path.rejected;
  out.steps = static_cast<int>(path.path.size()) - 1;
  for (const ContinuationPoint& pt : path.path)
    out.path.push_back(path_point(eq, reduction.motion(pt.x), pt.p));

  const Matrix6 k_end =
      path.jacobian.size() == 36 ? reduction.stiffness(path.jacobian) : eq.elastic_stiffness();
  const StabilityAnalysis s = stability_analysis(k_end, m, eq.length());
  out.static_mode = describe_mode(s.static_mode, points);
  out.dynamic_mode = describe_mode(s.dynamic_mode, points);
  out.mu = s.mu;
  switch (path.stop) {
    case ContinuationStop::LimitPoint:
    case ContinuationStop::NoConvergence:
      // The path cannot go on: a limit point (NoConvergence: the corrector
      // finds no equilibrium beyond it even at the minimum step).
      out.outcome = PathOutcome::LimitPoint;
      out.fos_limit_point = path.p_limit;
      // Equilibrium is lost at a limit point: by divergence unless the
      // critical pair is complex.
      out.stability = s.critical_complex ? StabilityKind::Flutter : StabilityKind::Divergence;
      if (path.stop == ContinuationStop::NoConvergence)
        out.notes.push_back("the path ends where no equilibrium is found at the minimum step");
      break;
    case ContinuationStop::ParameterBound:
    case ContinuationStop::TargetReached: {
      out.outcome = PathOutcome::NoLimitPoint;
      std::ostringstream note;
      note << "no limit point reached up to lambda = " << options.lambda_max;
      out.notes.push_back(note.str());
      out.stability = s.kind;
      break;
    }
    case ContinuationStop::StepBound: {
      out.outcome = PathOutcome::StepBudget;
      std::ostringstream note;
      note << "no limit point within " << options.max_steps << " steps (lambda reached "
           << path.p_limit << ")";
      out.notes.push_back(note.str());
      out.stability = s.kind;
      break;
    }
  }
  if (out.flutter_lambda && out.stability != StabilityKind::Flutter) {
    std::ostringstream note;
    note << "the tangent has complex eigenvalues (flutter of the linearised motion) from lambda = "
         << *out.flutter_lambda
         << ", while joints slip partly: a slipping joint's tangent is not symmetric (its "
            "friction is not associated with its dilation), which couples two modes of the "
            "block; equilibrium is not lost there";
    out.notes.push_back(note.str());
  }
  return out;
}

}  // namespace rockface::mechanics
