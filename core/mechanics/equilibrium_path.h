#pragma once
// The equilibrium path of one block and its first limit point (DESIGN.md,
// "mechanics"; SCENE.md analysis.stability = "equilibrium_path").
//
// The load factor lambda divides the shear strength of every joint (the
// joint law's strength divisor: strength reduction), so that the factor of
// safety is lambda at the first limit point of the path, the same
// definition as limit equilibrium's resisting / driving. The path runs in
// two parts:
//   1. loading: gravity and the scene's effects (and the in-situ stress)
//      are applied in increments with the strengths at 1 / lambda_start;
//      if no equilibrium is found there, the block fails under its loads
//      alone (it falls or topples whatever its joints' strength) and the
//      result says so;
//   2. strength reduction: arc-length continuation in (motion, lambda) from
//      lambda_start until the first limit point (dlambda/ds <= 0 or the path
//      turns flat: a mechanism), lambda_max (no limit point below it) or
//      max_steps (no limit point within the budget).
// At the end point: the static and dynamic failure modes and the stability
// of the equilibrium (stability_analysis.h): how equilibrium is lost at the
// limit point (divergence, or flutter when the critical pair is complex).
// Along the path every accepted point is checked for flutter too, which the
// static path cannot see: the first lambda with a complex pair is kept.
// The tangent is the joint laws' consistent one (exact, not differences).
// Such pairs before the limit are the tangent's, not rounding: a slipping
// contact's tangent is not symmetric (d shear / d closure is friction,
// kn tan(phi), d normal / d shear is dilation, -kn tan(d); a
// non-associated law has d < phi, Coulomb d = 0), and while some joints
// slip and others stick this couples two of the block's modes whose
// eigenvalues are close into a complex pair (the mode coupling of friction
// flutter). They come and go along the path; at the limit the critical mu
// is real (divergence) for sliding. The tangent is the loading branch's: a
// contact that unloads is elastic, so such a pair flags a possible
// oscillation of the linearised motion, not a loss of equilibrium.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/kinematics/effects/effect.h"
#include "core/mechanics/joint_law.h"
#include "core/mechanics/stability_analysis.h"

namespace rockface::mechanics {

struct MechanicsOptions {
  int contact_density = 3;     // sub-divisions per triangle edge of the joint faces
  double step = 0.05;          // initial arc-length step (lambda units)
  int max_steps = 400;         // accepted continuation steps
  double lambda_start = 0.05;  // strengths x 20 while the loads are applied
  double lambda_max = 20;      // no limit point below this: reported as such
  // The path's tangent by forward differences of the equilibrium instead of
  // the joint laws' consistent tangents (the earlier method; for comparison).
  bool difference_tangent = false;
  Progress* progress = nullptr;
};

// The options of `preset` (DESIGN.md): contact density and continuation step.
MechanicsOptions mechanics_options(Preset preset);

struct PathPoint {
  double lambda = 0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // of the centroid, m
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();     // rotation vector, rad
  double displacement = 0;                                // largest displacement of a vertex, m
};

enum class PathOutcome {
  LimitPoint,       // the first limit point was reached: fos_limit_point
  FailsUnderLoads,  // no equilibrium even with strengths x 1 / lambda_start
  NoLimitPoint,     // lambda_max reached without a limit point
  StepBudget,       // max_steps used up before a limit point
};
const char* outcome_name(PathOutcome o);

struct EquilibriumPath {
  PathOutcome outcome = PathOutcome::NoLimitPoint;
  std::optional<double> fos_limit_point;  // lambda at the first limit point
  RigidMode static_mode, dynamic_mode;    // at the limit (or last) point
  StabilityKind stability = StabilityKind::Stable;
  std::optional<double> flutter_lambda;  // first lambda with a complex pair of mu
  std::vector<std::complex<double>> mu;  // K z = mu M z at the limit (or last) point, 1/s^2
  std::vector<PathPoint> path;           // the strength-reduction part, lambda_start first
  int contacts = 0;
  int steps = 0, rejected_steps = 0, residual_evaluations = 0;
  std::vector<std::string> effects_used;  // effects acting on the block, plus in-situ stress
  std::vector<std::string> notes;
};

// plane_laws: one law per polyhedron plane (null for free faces); build
// them with make_joint_law (which checks the parameters).
EquilibriumPath equilibrium_path(const blocks::Polyhedron& block,
                                 const blocks::MassProperties& mass,
                                 const kinematics::Effects& effects,
                                 const std::vector<std::shared_ptr<const JointLaw>>& plane_laws,
                                 const std::optional<Eigen::Matrix3d>& insitu_stress,
                                 const MechanicsOptions& options);

}  // namespace rockface::mechanics
