#include "core/mechanics/coulomb_joint_law.h"

#include <cmath>

namespace rockface::mechanics {

CoulombJointLaw::CoulombJointLaw(const JointLawParameters& p)
    : kn_(p.normal_stiffness),
      ks_(p.normal_stiffness / (2.0 * (1.0 + p.poisson_ratio))),
      tan_phi_(std::tan(p.friction)),
      cohesion_(p.cohesion) {}

double CoulombJointLaw::strength(double sigma_n, const JointState& state) const {
  (void)state;
  return sigma_n > 0 ? cohesion_ + sigma_n * tan_phi_ : 0.0;
}

JointResponse CoulombJointLaw::respond(const JointState& committed, double closure,
                                       const Eigen::Vector2d& shear,
                                       double strength_divisor) const {
  JointResponse r;
  r.state = committed;
  if (!(closure > 0)) {
    r.state.slip = shear;
    r.stage = JointStage::Open;
    return r;
  }
  r.normal_stress = kn_ * closure;
  const Eigen::Vector2d trial = ks_ * (shear - committed.slip);
  const double trial_norm = trial.norm();
  r.shear_stress = trial;
  r.stage = committed.slip_length > 0 ? JointStage::PostPeak : JointStage::Elastic;
  r.tangent.diagonal() << kn_, ks_, ks_;
  if (strength_divisor <= 0) return r;
  const double limit = strength(r.normal_stress, committed) / strength_divisor;
  if (trial_norm <= limit) return r;
  // Radial return, exact for a constant strength.
  const double dg = (trial_norm - limit) / ks_;
  const Eigen::Vector2d dir = trial / trial_norm;
  r.state.slip += dg * dir;
  r.state.slip_length += dg;
  r.state.work += limit * dg;
  r.state.past_peak = true;
  r.shear_stress = limit * dir;
  r.stage = JointStage::PostPeak;
  r.slipping = true;
  // Tangent of the return: the traction's size follows the normal stress,
  // its direction the trial's (which turns by ks / |trial| per unit shear).
  r.tangent.block<2, 1>(1, 0) = kn_ * tan_phi_ / strength_divisor * dir;
  r.tangent.block<2, 2>(1, 1) =
      limit / trial_norm * ks_ * (Eigen::Matrix2d::Identity() - dir * dir.transpose());
  r.divisor_rate.tail<2>() = -limit / strength_divisor * dir;
  return r;
}

}  // namespace rockface::mechanics
