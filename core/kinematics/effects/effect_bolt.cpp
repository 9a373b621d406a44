#include "core/kinematics/effects/effect_bolt.h"

#include <cmath>

#include "core/common/error.h"
#include "core/kinematics/effects/effect_point_load.h"

namespace rockface::kinematics {

BoltEffect::BoltEffect(std::string label, const Eigen::Vector3d& point,
                       const Eigen::Vector3d& direction, double force)
    : label_(std::move(label)), point_(point), force_(force) {
  const double len = direction.norm();
  if (!(len > 0) || !std::isfinite(len)) throw InputError(label_, "bolt direction is zero");
  if (!(force >= 0) || !std::isfinite(force))
    throw InputError(label_ + ".force", "must be a non-negative number of newtons");
  direction_ = direction / len;
}

EffectLoad BoltEffect::load(const blocks::Polyhedron& block,
                            const blocks::MassProperties& mass) const {
  return point_load(block, mass, force_ * direction_, point_, label_);
}

}  // namespace rockface::kinematics
