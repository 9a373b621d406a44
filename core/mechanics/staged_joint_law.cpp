#include "core/mechanics/staged_joint_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

namespace {

// 9 delta_p of slip at the peak stress halves the roughness: W_c = 9 / ln 2 x delta_p x tau_p.
const double kSofteningSlips = 9.0 / std::numbers::ln2;

// Fixed-point passes for the normal stress of a slipping step (it changes
// with the step's dilation by kn x dv; the peak depends on it weakly).
constexpr int kStressPasses = 8;

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

JointResponse StagedJointLaw::respond(const JointState& committed, double closure,
                                      const Eigen::Vector2d& shear, double strength_divisor) const {
  JointResponse r;
  r.state = committed;
  const double sigma0 = kn_ * (closure + committed.dilation);
  if (!(sigma0 > 0)) {
    // Open: no tractions; the shear spring relaxes onto the displacement.
    r.state.slip = shear;
    r.stage = JointStage::Open;
    return r;
  }
  const Eigen::Vector2d trial = ks_ * (shear - committed.slip);
  const double trial_norm = trial.norm();
  r.normal_stress = sigma0;
  r.shear_stress = trial;
  r.stage = stage_of(sigma0, committed);
  if (strength_divisor <= 0 || trial_norm <= strength(sigma0, committed) / strength_divisor)
    return r;

  // Slip: radial return along the trial direction by dg, with the slip,
  // dilation, normal stress and softening it brings. The peak and the
  // dilation rate depend on the normal stress, which the dilation of the
  // step changes: a few fixed-point passes make them consistent.
  const Eigen::Vector2d dir = trial / trial_norm;
  auto advance_at = [&](double dg, double sigma_ref, double& sigma) {
    const double kappa_p = peak_slip(sigma_ref);
    const double tan_dp = p_.dilation
                              ? std::tan((peak_->peak_angle(sigma_ref) - peak_->residual_angle()) /
                                         p_.dilation_divisor)
                              : 0.0;
    JointState s = committed;
    s.slip += dg * dir;
    const double k0 = committed.slip_length, k1 = k0 + dg;
    s.slip_length = k1;
    double dv = 0;
    double excess = 0;  // slip past the peak in this step
    if (committed.past_peak) {
      dv = dilation_rate(sigma_ref, committed) * dg;
      excess = dg;
    } else if (kappa_p > 0 && k1 <= kappa_p) {
      dv = tan_dp * (k1 * k1 - k0 * k0) / (2 * kappa_p);
    } else {
      const double kb = std::max(std::min(kappa_p, k1), k0);
      dv = kappa_p > 0 ? tan_dp * (kb * kb - k0 * k0) / (2 * kappa_p) : 0.0;
      excess = k1 - kb;
      dv += tan_dp * excess;
    }
    if (excess > 0 && !s.past_peak) {
      s.past_peak = true;
      const double tau_p = sigma_ref * std::tan(peak_->peak_angle(sigma_ref));
      s.softening_energy =
          p_.softening_energy.value_or(kSofteningSlips * peak_->peak_displacement() * tau_p);
    }
    // Moving away from the origin of slip rides up the asperities.
    const double sense = s.slip.dot(dir) >= 0 ? 1.0 : -1.0;
    s.dilation = std::max(committed.dilation + sense * dv, 0.0);
    sigma = kn_ * std::max(closure + s.dilation, 0.0);
    if (excess > 0) s.work += strength(sigma, s) * excess;
    return s;
  };
  auto advance = [&](double dg, double& sigma) {
    double ref = sigma0;
    JointState s;
    for (int pass = 0; pass < kStressPasses; ++pass) {
      s = advance_at(dg, ref, sigma);
      if (!(sigma > 0) || std::abs(sigma - ref) <= kReturnMappingRel * sigma) break;
      ref = sigma;
    }
    return s;
  };
  // g(dg) = |trial| - ks dg - strength(dg) / divisor: positive at 0, not
  // positive at the full trial slip. Regula falsi with the Illinois
  // modification keeps the bracket and converges superlinearly (a handful
  // of evaluations where bisection takes ~40); it stops when the bracket or
  // |g| is below kReturnMappingRel of the trial.
  auto g_of = [&](double dg) {
    double sigma = 0;
    const JointState st = advance(dg, sigma);
    return trial_norm - ks_ * dg - strength(sigma, st) / strength_divisor;
  };
  double lo = 0, hi = trial_norm / ks_;
  double g_lo = g_of(lo), g_hi = g_of(hi);
  double root = hi;
  int side = 0;
  for (int it = 0; it < kReturnMappingIterations; ++it) {
    if (hi - lo <= kReturnMappingRel * (trial_norm / ks_)) break;
    double mid = g_lo != g_hi ? (lo * g_hi - hi * g_lo) / (g_hi - g_lo) : 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
    const double g = g_of(mid);
    if (std::abs(g) <= kReturnMappingRel * trial_norm) {
      root = mid;
      hi = lo = mid;
      break;
    }
    if (g > 0) {
      lo = mid;
      g_lo = g;
      if (side == 1) g_hi *= 0.5;
      side = 1;
    } else {
      hi = mid;
      g_hi = g;
      if (side == -1) g_lo *= 0.5;
      side = -1;
    }
    root = hi;
  }
  hi = root;
  double sigma = 0;
  r.state = advance(hi, sigma);
  r.normal_stress = sigma;
  r.shear_stress = (trial_norm - ks_ * hi) * dir;
  r.stage = stage_of(sigma, r.state);
  r.slipping = true;
  if (!(sigma > 0)) {
    r.stage = JointStage::Open;
    r.shear_stress.setZero();
  }
  return r;
}

}  // namespace rockface::mechanics
