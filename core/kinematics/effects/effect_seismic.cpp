#include "core/kinematics/effects/effect_seismic.h"

namespace rockface::kinematics {

EffectLoad SeismicEffect::load(const blocks::Polyhedron&,
                               const blocks::MassProperties& mass) const {
  EffectLoad l;
  // Pseudo-static: the inertial load of the ground acceleration, m a, acts
  // at the centroid like the weight.
  l.force = mass.mass * acceleration_;
  l.acts = true;
  return l;
}

}  // namespace rockface::kinematics
