#include "core/kinematics/effects/effect_point_load.h"

#include <Eigen/Geometry>

#include "core/blocks/point_location.h"

namespace rockface::kinematics {

EffectLoad point_load(const blocks::Polyhedron& block, const blocks::MassProperties& mass,
                      const Eigen::Vector3d& force, const Eigen::Vector3d& point,
                      const std::string& label) {
  EffectLoad l;
  const Eigen::Vector3d p = point - block.datum();
  if (blocks::locate_point(block, p) == blocks::PointLocation::Outside) {
    l.notes.push_back(label + " does not act on block " + block.id() +
                      ": its point is outside the block");
    return l;
  }
  l.force = force;
  l.moment = (p - mass.centroid).cross(force);
  l.acts = true;
  return l;
}

}  // namespace rockface::kinematics
