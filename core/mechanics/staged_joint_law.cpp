#include "core/mechanics/staged_joint_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/LU>

#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

namespace {

// 9 delta_p of slip at the peak stress halves the roughness: W_c = 9 / ln 2 x delta_p x tau_p.
const double kSofteningSlips = 9.0 / std::numbers::ln2;

}  // namespace

StagedJointLaw::StagedJointLaw(const JointLawParameters& p, std::unique_ptr<PeakStrength> peak)
    : p_(p),
      peak_(std::move(peak)),
      kn_(p.normal_stiffness),
      ks_(p.normal_stiffness / (2.0 * (1.0 + p.poisson_ratio))) {}

std::string StagedJointLaw::name() const {
  return p_.model == JointModel::Grasselli ? "grasselli" : "barton_bandis";
}

double StagedJointLaw::peak_slip(double sigma_n) const {
  const double tau_p = sigma_n * std::tan(peak_->peak_angle(sigma_n));
  return std::max(peak_->peak_displacement() - tau_p / ks_, 0.0);
}

double StagedJointLaw::softened_roughness(double sigma_n, const JointState& s) const {
  const double i_p = peak_->peak_angle(sigma_n) - peak_->residual_angle();
  if (!s.past_peak || !(s.softening_energy > 0)) return i_p;
  return i_p * std::exp(-s.work / s.softening_energy);
}

double StagedJointLaw::strength(double sigma_n, const JointState& s) const {
  if (!(sigma_n > 0)) return 0;
  const double phi_r = peak_->residual_angle();
  if (s.past_peak) return sigma_n * std::tan(phi_r + softened_roughness(sigma_n, s));
  const double tau_a = sigma_n * std::tan(phi_r);
  const double tau_p = sigma_n * std::tan(peak_->peak_angle(sigma_n));
  const double kappa_p = peak_slip(sigma_n);
  if (!(kappa_p > 0) || s.slip_length >= kappa_p) return tau_p;
  const double t = std::sqrt(s.slip_length / kappa_p);
  return tau_p - (1 - t) * (1 - t) * (tau_p - tau_a);
}

double StagedJointLaw::dilation_rate(double sigma_n, const JointState& s) const {
  if (!p_.dilation || !(sigma_n > 0)) return 0;
  if (s.past_peak) return std::tan(softened_roughness(sigma_n, s) / p_.dilation_divisor);
  const double tan_dp =
      std::tan((peak_->peak_angle(sigma_n) - peak_->residual_angle()) / p_.dilation_divisor);
  const double kappa_p = peak_slip(sigma_n);
  return kappa_p > 0 ? tan_dp * std::min(s.slip_length / kappa_p, 1.0) : tan_dp;
}

JointStage StagedJointLaw::stage_of(double sigma_n, const JointState& s) const {
  (void)sigma_n;
  if (s.past_peak) return JointStage::PostPeak;
  return s.slip_length > 0 ? JointStage::PrePeak : JointStage::Elastic;
}

StagedJointLaw::SlipUpdate StagedJointLaw::slip_update(const JointState& committed,
                                                       const Eigen::Vector2d& dir, const Dual& dg,
                                                       const Dual& sigma) const {
  const double phi_r = peak_->residual_angle();
  const Dual phi_p(peak_->peak_angle(sigma.value()),
                   peak_->peak_angle_slope(sigma.value()) * sigma.derivatives());
  const Dual i_p = phi_p - phi_r;
  const Dual tan_p = tan(phi_p);
  const Dual kappa_p = max(Dual(peak_->peak_displacement() - sigma * tan_p / ks_), Dual(0.0));
  const Dual tan_dp = p_.dilation ? tan(i_p / p_.dilation_divisor) : Dual(0.0);
  SlipUpdate u;
  u.state = committed;
  u.state.slip += dg.value() * dir;
  const double k0 = committed.slip_length;
  const Dual k1 = k0 + dg;
  u.state.slip_length = k1.value();
  // The softening energy: fixed when the peak was passed, or now.
  Dual wc = committed.softening_energy;
  auto softened = [&](const Dual& work) -> Dual {
    return wc.value() > 0 ? i_p * exp(-work / wc) : i_p;
  };
  Dual dv = 0.0;
  Dual excess = 0.0;  // slip past the peak in this step
  if (committed.past_peak) {
    if (p_.dilation) dv = tan(softened(committed.work) / p_.dilation_divisor) * dg;
    excess = dg;
  } else if (kappa_p.value() > 0 && k1.value() <= kappa_p.value()) {
    dv = tan_dp * (k1 * k1 - k0 * k0) / (2.0 * kappa_p);
  } else {
    const Dual kb = max(min(kappa_p, k1), Dual(k0));
    if (kappa_p.value() > 0) dv = tan_dp * (kb * kb - k0 * k0) / (2.0 * kappa_p);
    excess = k1 - kb;
    dv += tan_dp * excess;
  }
  if (excess.value() > 0 && !committed.past_peak) {
    u.state.past_peak = true;
    wc = p_.softening_energy ? Dual(*p_.softening_energy)
                             : kSofteningSlips * peak_->peak_displacement() * sigma * tan_p;
  }
  // Moving away from the origin of slip rides up the asperities.
  const double sense = u.state.slip.dot(dir) >= 0 ? 1.0 : -1.0;
  const Dual v = committed.dilation + sense * dv;
  u.dilation = v.value() > 0 ? v : Dual(0.0);
  u.state.dilation = u.dilation.value();
  if (u.state.past_peak) {
    Dual work = committed.work;
    if (excess.value() > 0) work += sigma * tan(phi_r + softened(work)) * excess;
    u.state.work = work.value();
    u.state.softening_energy = wc.value();
    u.strength = sigma * tan(phi_r + softened(work));
  } else if (kappa_p.value() > 0 && k1.value() < kappa_p.value()) {
    const Dual t = sqrt(k1 / kappa_p);
    const Dual one_minus = 1.0 - t;
    u.strength = sigma * (tan_p - one_minus * one_minus * (tan_p - std::tan(phi_r)));
  } else {
    u.strength = sigma * tan_p;
  }
  return u;
}

double StagedJointLaw::closed_form_slip(const JointState& committed, double sigma0,
                                        double trial_norm, double divisor) const {
  if (!(sigma0 > 0)) return -1;  // no closed form: the caller bisects
  const double tan_p = std::tan(peak_->peak_angle(sigma0));
  if (committed.past_peak)
    return std::max(trial_norm - strength(sigma0, committed) / divisor, 0.0) / ks_;
  const double kappa_p = peak_slip(sigma0);
  const double k0 = committed.slip_length;
  if (!(kappa_p > k0)) return std::max(trial_norm - sigma0 * tan_p / divisor, 0.0) / ks_;
  // |trial| - ks (kappa_p s^2 - k0) = sigma0 (tan_p - (1 - s)^2 (tan_p - tan_r)) / divisor
  // in s = sqrt(kappa / kappa_p): a s^2 + b s + c = 0, decreasing in s on [s0, 1].
  const double spread = sigma0 * (tan_p - std::tan(peak_->residual_angle())) / divisor;
  const double a = spread - ks_ * kappa_p;
  const double b = -2 * spread;
  const double c = trial_norm + ks_ * k0 - sigma0 * std::tan(peak_->residual_angle()) / divisor;
  const double s0 = std::sqrt(k0 / kappa_p);
  auto g = [&](double s) { return (a * s + b) * s + c; };
  if (g(1.0) > 0) return kappa_p - k0 + std::max(g(1.0), 0.0) / ks_;  // past the peak
  const double disc = std::max(b * b - 4 * a * c, 0.0);
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  for (const double s : {q / a, c / q})
    if (std::isfinite(s) && s >= s0 && s <= 1.0) return kappa_p * s * s - k0;
  return 0.5 * (kappa_p - k0);
}

JointResponse StagedJointLaw::respond(const JointState& committed, double closure,
                                      const Eigen::Vector2d& shear, double strength_divisor) const {
  JointResponse r;
  r.state = committed;
  const double sigma0 = kn_ * (closure + committed.dilation);
  const Eigen::Vector2d trial = ks_ * (shear - committed.slip);
  const double trial_norm = trial.norm();
  bool contact = sigma0 > 0;
  if (!contact && strength_divisor > 0 && trial_norm > 0 && p_.dilation) {
    // Open at the committed dilation, but the shear that moves it rides up
    // the asperities: a contact whose dilation, slipping the whole trial,
    // closes it again carries the stress that slip leaves (a stiff joint
    // under a lifting block lives there; calling it open would give a
    // residual that jumps with each Newton iterate).
    const SlipUpdate whole =
        slip_update(committed, trial / trial_norm, Dual(trial_norm / ks_), Dual(0.0));
    contact = closure + whole.dilation.value() > 0;
  }
  if (!contact) {
    // Open: no tractions; the shear spring relaxes onto the displacement.
    r.state.slip = shear;
    r.stage = JointStage::Open;
    return r;
  }
  r.normal_stress = std::max(sigma0, 0.0);
  r.shear_stress = trial;
  r.stage = stage_of(sigma0, committed);
  r.tangent.diagonal() << kn_, ks_, ks_;
  if (strength_divisor <= 0 ||
      trial_norm <= strength(r.normal_stress, committed) / strength_divisor)
    return r;

  // Slip: radial return along the trial direction. Unknowns dg (slip) and
  // sigma (normal stress at the end of the step):
  //   F(dg, sigma) = sigma - kn max(closure + v(dg, sigma), 0) = 0,
  //   G(dg, sigma) = |trial| - ks dg - S(dg, sigma) / divisor = 0.
  // For each dg, F is solved for sigma by Newton (bracketed: F(0) <= 0);
  // G(dg) with dsigma/ddg = -F_dg / F_sigma by Newton from the closed-form
  // slip, inside the bracket [0, |trial| / ks] that G's signs keep.
  const Eigen::Vector2d dir = trial / trial_norm;
  struct Point {
    double sigma = 0;
    SlipUpdate u;
    double f_dg = 0, f_sigma = 1;  // partials of F
  };
  auto normal_stress = [&](double dg, double guess) {
    Point pt;
    auto at = [&](double sigma) {
      pt.sigma = sigma;
      pt.u = slip_update(committed, dir, dual_variable(dg, 0), dual_variable(sigma, 1));
      const double gap = closure + pt.u.dilation.value();
      pt.f_dg = gap > 0 ? -kn_ * pt.u.dilation.derivatives()(0) : 0.0;
      pt.f_sigma = gap > 0 ? 1 - kn_ * pt.u.dilation.derivatives()(1) : 1.0;
      return sigma - kn_ * std::max(gap, 0.0);
    };
    const double f0 = at(0.0);
    if (f0 >= 0) return pt;  // open: no dilation of this slip closes it
    double lo = 0, hi = INFINITY, x = guess > 0 ? guess : -f0;
    for (int it = 0; it < kReturnMappingIterations; ++it) {
      const double f = at(x);
      if (std::abs(f) <= kReturnMappingRel * x) break;
      (f > 0 ? hi : lo) = x;
      double next = x - f / pt.f_sigma;
      if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * x;
      if (std::isfinite(hi) && hi - lo <= kReturnMappingRel * hi) break;
      x = next;
    }
    return pt;
  };
  const double dg_max = trial_norm / ks_;
  double lo = 0, hi = dg_max;
  double dg = closed_form_slip(committed, sigma0, trial_norm, strength_divisor);
  if (!(dg > lo && dg < hi)) dg = 0.5 * (lo + hi);
  Point pt;
  double guess = sigma0;
  for (int it = 0;; ++it) {
    pt = normal_stress(dg, guess);
    if (it == kReturnMappingIterations) break;  // pt stays the point of dg
    guess = pt.sigma;
    const double g = trial_norm - ks_ * dg - pt.u.strength.value() / strength_divisor;
    if (std::abs(g) <= kReturnMappingRel * trial_norm) break;
    (g > 0 ? lo : hi) = dg;
    const double dsigma = -pt.f_dg / pt.f_sigma;
    const double slope =
        -ks_ - (pt.u.strength.derivatives()(0) + pt.u.strength.derivatives()(1) * dsigma) /
                   strength_divisor;
    double next = dg - g / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= kReturnMappingRel * dg_max) break;
    dg = next;
  }
  r.state = pt.u.state;
  r.normal_stress = pt.sigma;
  const double tau = trial_norm - ks_ * dg;
  r.shear_stress = tau * dir;
  r.stage = stage_of(pt.sigma, r.state);
  r.slipping = true;
  r.tangent.setZero();
  if (!(pt.sigma > 0)) {
    r.stage = JointStage::Open;
    r.shear_stress.setZero();
    return r;
  }
  // Consistent tangent: d(dg, sigma) / d(closure, |trial|, divisor) from
  // the implicit function theorem on (F, G) at the solution.
  const double s = pt.u.strength.value();
  Eigen::Matrix2d a;
  a << pt.f_dg, pt.f_sigma, -ks_ - pt.u.strength.derivatives()(0) / strength_divisor,
      -pt.u.strength.derivatives()(1) / strength_divisor;
  Eigen::Matrix<double, 2, 3> b;
  b << -kn_, 0, 0, 0, 1, s / (strength_divisor * strength_divisor);
  const Eigen::Matrix<double, 2, 3> d = -a.inverse() * b;   // rows dg, sigma
  const Eigen::RowVector2d dtrial = ks_ * dir.transpose();  // d|trial| / d shear
  r.tangent(0, 0) = d(1, 0);
  r.tangent.block<1, 2>(0, 1) = d(1, 1) * dtrial;
  r.tangent.block<2, 1>(1, 0) = -ks_ * d(0, 0) * dir;
  r.tangent.block<2, 2>(1, 1) =
      dir * (dtrial - ks_ * d(0, 1) * dtrial) +
      tau / trial_norm * ks_ * (Eigen::Matrix2d::Identity() - dir * dir.transpose());
  r.divisor_rate << d(1, 2), -ks_ * d(0, 2) * dir;
  return r;
}

}  // namespace rockface::mechanics
