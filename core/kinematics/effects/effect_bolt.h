#pragma once
// A bolt or anchor (SCENE.md effects.bolts): pulls the block with `force`
// along the unit direction of (trend, plunge), applied at its point (the
// bolt head, on or in the block). A bolt whose point is not on or in the
// block does not act on it and says so.
#include "core/kinematics/effects/effect.h"

namespace rockface::kinematics {

class BoltEffect final : public Effect {
 public:
  // label names the bolt in notes ("bolts[0]"); point absolute; direction
  // need not be unit; force in N (>= 0).
  BoltEffect(std::string label, const Eigen::Vector3d& point, const Eigen::Vector3d& direction,
             double force);
  std::string name() const override { return "bolts"; }
  EffectLoad load(const blocks::Polyhedron& block,
                  const blocks::MassProperties& mass) const override;

 private:
  std::string label_;
  Eigen::Vector3d point_, direction_;
  double force_;
};

}  // namespace rockface::kinematics
