#include "core/analysis/scene_effects.h"

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/effects/effect_bolt.h"
#include "core/kinematics/effects/effect_force.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/kinematics/effects/effect_seismic.h"
#include "core/kinematics/effects/effect_water.h"

namespace rockface::analysis {

kinematics::Effects scene_effects(const AnalysisInput& scene) {
  kinematics::Effects effects;
  effects.push_back(std::make_unique<kinematics::GravityEffect>(scene.gravity));
  try {
    if (const auto& w = scene.effects.water) {
      std::vector<int> joints;
      for (const auto& id : w->joints) joints.push_back(scene.plane_index(id));
      effects.push_back(std::make_unique<kinematics::WaterEffect>(
          w->unit_weight, w->phreatic_point,
          geometry::plane_normal_deg(w->phreatic_dip, w->phreatic_dipdir), joints));
    }
    if (scene.effects.seismic)
      effects.push_back(std::make_unique<kinematics::SeismicEffect>(*scene.effects.seismic));
    for (size_t k = 0; k < scene.effects.forces.size(); ++k) {
      const auto& f = scene.effects.forces[k];
      effects.push_back(std::make_unique<kinematics::ForceEffect>(
          "effects.forces[" + std::to_string(k) + "]", f.vector, f.point,
          f.frame == "block" ? kinematics::ForceFrame::Block : kinematics::ForceFrame::Space));
    }
    for (size_t k = 0; k < scene.effects.bolts.size(); ++k) {
      const auto& b = scene.effects.bolts[k];
      effects.push_back(std::make_unique<kinematics::BoltEffect>(
          "effects.bolts[" + std::to_string(k) + "]", b.point,
          geometry::line_direction({deg_to_rad(b.trend), deg_to_rad(b.plunge)}), b.force));
    }
  } catch (const InputError& e) {
    throw InputError(scene.source + ": " + e.where(), e.reason());
  }
  return effects;
}

}  // namespace rockface::analysis
