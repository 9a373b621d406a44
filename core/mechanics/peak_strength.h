#pragma once
// Peak shear strength of a rough joint, as a mobilised friction angle
// phi_r + i at a normal stress: Barton-Bandis (with the scale corrections
// of Barton & Bandis 1982) or Grasselli (Grasselli & Egger 2003). The
// staged joint law (staged_joint_law.h) walks from stage A to this peak and
// softens from it.
#include <memory>

#include "core/mechanics/joint_law.h"

namespace rockface::mechanics {

class PeakStrength {
 public:
  virtual ~PeakStrength() = default;
  // Residual friction angle phi_r (radians): where softening ends and where
  // the elastic stage A ends (no roughness mobilised yet).
  virtual double residual_angle() const = 0;
  // Peak friction angle phi_r + i (radians) at sigma_n > 0 (Pa).
  virtual double peak_angle(double sigma_n) const = 0;
  // d peak_angle / d sigma_n (radians per Pa): the staged law's analytic
  // tangent needs how the peak moves with the normal stress. 0 where the
  // angle is capped.
  virtual double peak_angle_slope(double sigma_n) const = 0;
  // Shear displacement at the peak (m).
  virtual double peak_displacement() const = 0;
};

// Barton-Bandis: tau_p = sigma_n tan(phi_r + JRC_n log10(JCS_n / sigma_n)),
// capped at kMaxPeakFrictionDeg and with i >= 0 (sigma_n above JCS
// mobilises no roughness). Scale corrections when a field length Ln is
// given: JRC_n = JRC (Ln/L0)^(-0.02 JRC), JCS_n = JCS (Ln/L0)^(-0.03 JRC).
// Peak displacement delta_p = Ln / 500 (JRC_n / Ln)^0.33 (lengths in m).
class BartonBandisPeak final : public PeakStrength {
 public:
  explicit BartonBandisPeak(const JointLawParameters& p);
  double residual_angle() const override { return phi_r_; }
  double peak_angle(double sigma_n) const override;
  double peak_angle_slope(double sigma_n) const override;
  double peak_displacement() const override { return delta_p_; }
  double jrc() const { return jrc_n_; }  // after the scale correction
  double jcs() const { return jcs_n_; }

 private:
  double phi_r_, jrc_n_, jcs_n_, delta_p_;
};

// Grasselli: tau_p = (1 + exp(-theta*max / (9 A0 (C + 1)) sigma_n / sigma_t))
//                    sigma_n tan(phi_r + (theta*max / C)^1.18)
// with theta*max in degrees inside the power, as published (shear along
// the foliation, alpha = 0). Grasselli's criterion gives no peak
// displacement: Barton-Bandis's, from the law's JRC and lengths, is used.
class GrasselliPeak final : public PeakStrength {
 public:
  explicit GrasselliPeak(const JointLawParameters& p);
  double residual_angle() const override { return phi_r_; }
  double peak_angle(double sigma_n) const override;
  double peak_angle_slope(double sigma_n) const override;
  double peak_displacement() const override { return delta_p_; }

 private:
  double phi_r_, a0_, theta_max_deg_, c_, sigma_t_, delta_p_;
};

std::unique_ptr<PeakStrength> make_peak_strength(const JointLawParameters& p);

}  // namespace rockface::mechanics
