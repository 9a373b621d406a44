#include "core/kinematics/effects/effect_gravity.h"

namespace rockface::kinematics {

EffectLoad GravityEffect::load(const blocks::Polyhedron&,
                               const blocks::MassProperties& mass) const {
  EffectLoad l;
  l.force = mass.mass * gravity_;  // at the centroid: no moment about it
  l.acts = true;
  return l;
}

}  // namespace rockface::kinematics
