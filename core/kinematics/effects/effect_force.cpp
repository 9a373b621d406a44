#include "core/kinematics/effects/effect_force.h"

#include "core/kinematics/effects/effect_point_load.h"

namespace rockface::kinematics {

ForceEffect::ForceEffect(std::string label, const Eigen::Vector3d& vector,
                         const Eigen::Vector3d& point, ForceFrame frame)
    : label_(std::move(label)), vector_(vector), point_(point), frame_(frame) {}

EffectLoad ForceEffect::load(const blocks::Polyhedron& block,
                             const blocks::MassProperties& mass) const {
  // A follower (block frame) force turns with the block; in the initial
  // position, the one limit equilibrium looks at, both frames coincide.
  (void)frame_;
  return point_load(block, mass, vector_, point_, label_);
}

}  // namespace rockface::kinematics
