#include "core/mechanics/peak_strength.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/units.h"
#include "core/mechanics/tolerances.h"

namespace rockface::mechanics {

namespace {

double cap_peak(double phi_r, double angle) {
  return std::clamp(angle, phi_r, std::max(phi_r, deg_to_rad(kMaxPeakFrictionDeg)));
}

// Barton & Bandis (1982): peak shear displacement of a joint of length L (m).
double barton_peak_displacement(double length, double jrc) {
  return length / 500.0 * std::pow(std::max(jrc, 0.0) / length, 0.33);
}

}  // namespace

BartonBandisPeak::BartonBandisPeak(const JointLawParameters& p)
    : phi_r_(p.phi_r.value_or(p.phi_b)), jrc_n_(p.jrc), jcs_n_(p.jcs) {
  double length = p.lab_length;
  if (p.field_length) {
    const double ratio = *p.field_length / p.lab_length;
    jrc_n_ = p.jrc * std::pow(ratio, -0.02 * p.jrc);
    jcs_n_ = p.jcs * std::pow(ratio, -0.03 * p.jrc);
    length = *p.field_length;
  }
  delta_p_ = barton_peak_displacement(length, jrc_n_);
}

double BartonBandisPeak::peak_angle(double sigma_n) const {
  // Barton's i = JRC log10(JCS / sigma_n) is in degrees.
  const double i_deg = jrc_n_ * std::log10(jcs_n_ / sigma_n);
  return cap_peak(phi_r_, phi_r_ + deg_to_rad(std::max(i_deg, 0.0)));
}

double BartonBandisPeak::peak_angle_slope(double sigma_n) const {
  const double i_deg = jrc_n_ * std::log10(jcs_n_ / sigma_n);
  const double angle = phi_r_ + deg_to_rad(i_deg);
  // Capped (70 degrees) or no roughness mobilised (sigma_n >= JCS): flat.
  if (!(i_deg > 0) || angle >= deg_to_rad(kMaxPeakFrictionDeg)) return 0;
  return -deg_to_rad(jrc_n_ / (sigma_n * std::numbers::ln10));
}

GrasselliPeak::GrasselliPeak(const JointLawParameters& p)
    : phi_r_(p.phi_r.value_or(p.phi_b)),
      a0_(p.contact_area),
      theta_max_deg_(rad_to_deg(p.theta_max)),
      c_(p.roughness_c),
      sigma_t_(p.tensile_strength),
      delta_p_(barton_peak_displacement(p.field_length.value_or(p.lab_length), p.jrc)) {}

double GrasselliPeak::peak_angle(double sigma_n) const {
  const double factor =
      1.0 + std::exp(-theta_max_deg_ / (9.0 * a0_ * (c_ + 1.0)) * sigma_n / sigma_t_);
  const double angle = phi_r_ + deg_to_rad(std::pow(theta_max_deg_ / c_, 1.18));
  return cap_peak(phi_r_, std::atan(factor * std::tan(angle)));
}

double GrasselliPeak::peak_angle_slope(double sigma_n) const {
  const double rate = theta_max_deg_ / (9.0 * a0_ * (c_ + 1.0)) / sigma_t_;
  const double factor = 1.0 + std::exp(-rate * sigma_n);
  const double tan_angle = std::tan(phi_r_ + deg_to_rad(std::pow(theta_max_deg_ / c_, 1.18)));
  const double raw = std::atan(factor * tan_angle);
  if (raw <= phi_r_ || raw >= std::max(phi_r_, deg_to_rad(kMaxPeakFrictionDeg))) return 0;
  const double x = factor * tan_angle;
  return -rate * std::exp(-rate * sigma_n) * tan_angle / (1 + x * x);
}

std::unique_ptr<PeakStrength> make_peak_strength(const JointLawParameters& p) {
  if (p.model == JointModel::Grasselli) return std::make_unique<GrasselliPeak>(p);
  return std::make_unique<BartonBandisPeak>(p);
}

}  // namespace rockface::mechanics
