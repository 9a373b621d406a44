#pragma once
// A force at a point of a block: shared by applied forces and bolts. It acts
// when the point is inside the block or on its surface.
#include <string>

#include "core/kinematics/effects/effect.h"

namespace rockface::kinematics {

// point: absolute. label names the load in the note when it does not act.
EffectLoad point_load(const blocks::Polyhedron& block, const blocks::MassProperties& mass,
                      const Eigen::Vector3d& force, const Eigen::Vector3d& point,
                      const std::string& label);

}  // namespace rockface::kinematics
