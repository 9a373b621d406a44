#pragma once
// Gravity: the block's weight m g at its centroid (always simulated).
#include "core/kinematics/effects/effect.h"

namespace rockface::kinematics {

class GravityEffect final : public Effect {
 public:
  explicit GravityEffect(const Eigen::Vector3d& gravity) : gravity_(gravity) {}
  std::string name() const override { return "gravity"; }
  EffectLoad load(const blocks::Polyhedron& block,
                  const blocks::MassProperties& mass) const override;

 private:
  Eigen::Vector3d gravity_;  // m/s^2
};

}  // namespace rockface::kinematics
