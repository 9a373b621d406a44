#pragma once
// Pseudo-static seismic load: m a at the centroid, a the scene's
// acceleration (m/s^2).
#include "core/kinematics/effects/effect.h"

namespace rockface::kinematics {

class SeismicEffect final : public Effect {
 public:
  explicit SeismicEffect(const Eigen::Vector3d& acceleration) : acceleration_(acceleration) {}
  std::string name() const override { return "seismic"; }
  EffectLoad load(const blocks::Polyhedron& block,
                  const blocks::MassProperties& mass) const override;

 private:
  Eigen::Vector3d acceleration_;
};

}  // namespace rockface::kinematics
