#pragma once
// Elastic-perfectly plastic Coulomb joint: tau <= c + sigma_n tan(phi), no
// dilation, no tension. With a very stiff joint it is rigid-plastic: the
// joint of limit equilibrium.
#include "core/mechanics/joint_law.h"

namespace rockface::mechanics {

class CoulombJointLaw final : public JointLaw {
 public:
  explicit CoulombJointLaw(const JointLawParameters& p);
  std::string name() const override { return "coulomb"; }
  double normal_stiffness() const override { return kn_; }
  double shear_stiffness() const override { return ks_; }
  double strength(double sigma_n, const JointState& state) const override;
  JointResponse respond(const JointState& committed, double closure, const Eigen::Vector2d& shear,
                        double strength_divisor) const override;

 private:
  double kn_, ks_, tan_phi_, cohesion_;
};

}  // namespace rockface::mechanics
