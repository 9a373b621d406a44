#pragma once
// The staged joint law: stage A elastic, stage B pre-peak hardening with
// growing dilation, stage C post-peak softening in the dissipated shear
// energy; peak from Barton-Bandis or Grasselli (peak_strength.h).
//
// Under a normal stress sigma_n, with tau_A = sigma_n tan(phi_r) and
// tau_p = sigma_n tan(phi_peak(sigma_n)), the monotone curve tau(u) is:
//   A: tau = ks u up to u_A = tau_A / ks (the joint slips once its basic
//      friction is overcome: Barton's mobilised JRC is zero there);
//   B: the quadratic Bezier curve from (u_A, tau_A) through the control
//      point (tau_p / ks, tau_p) (where the elastic line meets the peak
//      level, so the curve leaves A with slope ks) to the peak
//      (u_p, tau_p), u_p = max(delta_p, tau_p / ks), arriving with slope 0.
//      Its plastic slip u - tau / ks is t^2 kappa_p (kappa_p = u_p - tau_p /
//      ks), so the strength in terms of the slip kappa is closed-form:
//      tau_B(kappa) = tau_p - (1 - sqrt(kappa / kappa_p))^2 (tau_p - tau_A);
//   C: the roughness softens with the energy W dissipated after the peak
//      (Plesha's rule): i = i_p exp(-W / W_c), tau = sigma_n tan(phi_r + i).
//      W_c defaults to 9 / ln 2 x delta_p x tau_p, which halves the
//      roughness after 9 delta_p of slip at the peak stress (Barton's table
//      of mobilised JRC: half the peak at ten times the peak displacement).
// Dilation (rate dv = tan(d) |d kappa|, d = mobilised roughness / M):
// none in A, a rate growing linearly with the slip in B (so v(kappa) is the
// quadratic Bezier from (0, 0) via (kappa_p / 2, 0) to (kappa_p,
// tan(d_p) kappa_p / 2)), tan(i / M) in C. Slip back towards the origin
// rides down the asperities: dilation decreases, never below zero.
// Hardening is isotropic in the accumulated slip; slip is a radial return.
//
// The return of a slipping step solves two equations in the slip dg and
// the normal stress sigma at the end of the step: sigma = kn (closure +
// v(dg, sigma)) (the dilation of the step loads the normal spring) and
// |trial| - ks dg = S(dg, sigma) / divisor. In stage B with sigma fixed the
// second is a quadratic in sqrt(slip / kappa_p), solved in closed form: the
// return is exact without dilation, and it is the start of a Newton
// iteration otherwise (a stiff joint's dilation changes sigma by kn x dv,
// which a fixed point on sigma does not survive at 1e12 Pa/m). The explicit
// update is evaluated on dual numbers, so Newton and the consistent tangent
// (JointResponse::tangent, by the implicit function theorem at the
// solution) use its exact derivatives.
#include <memory>

#include "core/mechanics/dual_number.h"
#include "core/mechanics/joint_law.h"
#include "core/mechanics/peak_strength.h"

namespace rockface::mechanics {

class StagedJointLaw final : public JointLaw {
 public:
  StagedJointLaw(const JointLawParameters& p, std::unique_ptr<PeakStrength> peak);
  std::string name() const override;
  double normal_stiffness() const override { return kn_; }
  double shear_stiffness() const override { return ks_; }
  double slip_scale() const override { return peak_->peak_displacement(); }
  double strength(double sigma_n, const JointState& state) const override;
  JointResponse respond(const JointState& committed, double closure, const Eigen::Vector2d& shear,
                        double strength_divisor) const override;

  const PeakStrength& peak() const { return *peak_; }
  // Plastic slip at the peak under sigma_n (kappa_p above), m.
  double peak_slip(double sigma_n) const;
  // Dilation rate tan(d) at the slip and history of `state`.
  double dilation_rate(double sigma_n, const JointState& state) const;
  // Roughness angle i (radians) mobilised after the peak, at energy W.
  double softened_roughness(double sigma_n, const JointState& state) const;

 private:
  // The explicit update of a slipping step: slip dg along dir at the normal
  // stress sigma (duals in (dg, sigma)) -> the state after the step, its
  // dilation v and its strength S (before the divisor).
  struct SlipUpdate {
    JointState state;
    Dual dilation;
    Dual strength;
  };
  SlipUpdate slip_update(const JointState& committed, const Eigen::Vector2d& dir, const Dual& dg,
                         const Dual& sigma) const;
  // The slip of the step in closed form with sigma held at sigma0 (stage
  // B's quadratic; perfectly plastic at the current strength otherwise).
  double closed_form_slip(const JointState& committed, double sigma0, double trial_norm,
                          double divisor) const;
  JointStage stage_of(double sigma_n, const JointState& s) const;

  JointLawParameters p_;
  std::unique_ptr<PeakStrength> peak_;
  double kn_, ks_;
};

}  // namespace rockface::mechanics
