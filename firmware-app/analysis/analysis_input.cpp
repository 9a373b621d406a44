#include "firmware-app/analysis/analysis_input.h"

#include <algorithm>

namespace rockface::app {

const storage::SceneJoint* AnalysisInput::joint(const std::string& id) const {
  const auto j =
      std::find_if(joints.begin(), joints.end(), [&](const auto& p) { return p.id == id; });
  return j == joints.end() ? nullptr : &*j;
}

int AnalysisInput::plane_index(const std::string& id) const {
  const auto named = [&](const auto& plane) { return plane.id == id; };
  if (const auto j = std::find_if(joints.begin(), joints.end(), named); j != joints.end())
    return static_cast<int>(j - joints.begin());
  if (const auto f = std::find_if(free_faces.begin(), free_faces.end(), named);
      f != free_faces.end())
    return static_cast<int>(joints.size()) + static_cast<int>(f - free_faces.begin());
  return -1;
}

AnalysisInput analysis_input(const storage::Scene& scene) {
  AnalysisInput in;
  in.source = scene.source;
  in.datum = scene.datum;
  in.has_datum = scene.has_datum;
  in.density = scene.density;
  in.gravity = scene.gravity;
  in.joints = scene.joints;
  in.free_faces = scene.free_faces;
  in.blocks = scene.blocks;
  in.patches = scene.patches;
  in.traces = scene.traces;
  in.analysis = scene.analysis;
  in.effects = scene.effects;
  return in;
}

}  // namespace rockface::app
