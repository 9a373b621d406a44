#include "core/mechanics/joint_law.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/mechanics/coulomb_joint_law.h"
#include "core/mechanics/peak_strength.h"
#include "core/mechanics/staged_joint_law.h"

namespace rockface::mechanics {

namespace {

void require(bool ok, const char* field, const std::string& reason) {
  if (!ok) throw InputError(std::string("joint_law.") + field, reason);
}

void require_positive(double v, const char* field, const char* unit) {
  require(std::isfinite(v) && v > 0, field,
          format_significant(v, 6) + " must be a positive number of " + unit);
}

void require_angle(double rad, const char* field) {
  require(std::isfinite(rad) && rad >= 0 && rad < kPi / 2, field,
          format_significant(rad_to_deg(rad), 6) + " degrees is outside [0, 90)");
}

}  // namespace

const char* stage_name(JointStage s) {
  switch (s) {
    case JointStage::Open:
      return "open";
    case JointStage::Elastic:
      return "elastic";
    case JointStage::PrePeak:
      return "pre-peak";
    case JointStage::PostPeak:
      return "post-peak";
  }
  return "?";
}

std::unique_ptr<JointLaw> make_joint_law(const JointLawParameters& p) {
  require(
      std::isfinite(p.normal_stiffness) && p.normal_stiffness > 0, "normal_stiffness",
      format_significant(p.normal_stiffness, 6) + " Pa/m: a joint's stiffness must be positive");
  require(std::isfinite(p.poisson_ratio) && p.poisson_ratio > -1 && p.poisson_ratio < 0.5,
          "poisson_ratio", format_significant(p.poisson_ratio, 6) + " is outside (-1, 0.5)");
  if (p.model == JointModel::Coulomb) {
    require_angle(p.friction, "friction");
    require(std::isfinite(p.cohesion) && p.cohesion >= 0, "cohesion",
            format_significant(p.cohesion, 6) + " Pa must not be negative");
    return std::make_unique<CoulombJointLaw>(p);
  }
  require(std::isfinite(p.jrc) && p.jrc >= 0 && p.jrc <= 20, "jrc",
          format_significant(p.jrc, 6) + " is outside Barton's range [0, 20]");
  require_positive(p.jcs, "jcs", "Pa");
  require_angle(p.phi_b, "phi_b");
  if (p.phi_r) require_angle(*p.phi_r, "phi_r");
  require_positive(p.lab_length, "lab_length", "m");
  if (p.field_length) require_positive(*p.field_length, "field_length", "m");
  require_positive(p.dilation_divisor, "dilation_divisor", "(dimensionless)");
  if (p.softening_energy) require_positive(*p.softening_energy, "softening_energy", "J/m^2");
  if (p.model == JointModel::Grasselli) {
    require(std::isfinite(p.contact_area) && p.contact_area > 0 && p.contact_area <= 1,
            "contact_area", format_significant(p.contact_area, 6) + " is outside (0, 1]");
    require(std::isfinite(p.theta_max) && p.theta_max > 0 && p.theta_max <= kPi / 2, "theta_max",
            format_significant(rad_to_deg(p.theta_max), 6) + " degrees is outside (0, 90]");
    require_positive(p.roughness_c, "roughness_c", "(dimensionless)");
    require_positive(p.tensile_strength, "tensile_strength", "Pa");
  }
  return std::make_unique<StagedJointLaw>(p, make_peak_strength(p));
}

}  // namespace rockface::mechanics
