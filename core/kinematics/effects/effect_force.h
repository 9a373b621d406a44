#pragma once
// An applied force at a point (SCENE.md effects.forces). It acts on the
// block that contains its point (inside or on the surface, within
// kOnSurfaceRel x size); on other blocks it does not act and says so.
// "space" forces keep their direction; "block" forces follow the block's
// rotation (identical at the initial position used by limit equilibrium).
#include "core/kinematics/effects/effect.h"

namespace rockface::kinematics {

enum class ForceFrame { Space, Block };

class ForceEffect final : public Effect {
 public:
  // label names the force in notes ("forces[0]"); point is absolute.
  ForceEffect(std::string label, const Eigen::Vector3d& vector, const Eigen::Vector3d& point,
              ForceFrame frame);
  std::string name() const override { return "forces"; }
  EffectLoad load(const blocks::Polyhedron& block,
                  const blocks::MassProperties& mass) const override;
  // Whether the force follows the block's rotation (the equilibrium path).
  ForceFrame frame() const { return frame_; }

 private:
  std::string label_;
  Eigen::Vector3d vector_, point_;
  ForceFrame frame_;
};

}  // namespace rockface::kinematics
