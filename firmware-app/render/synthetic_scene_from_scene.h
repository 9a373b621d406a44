#pragma once
// A parsed scene's imaging section, surface and joints, as the synthetic
// renderer's input. Lives here because the camera part may not use storage.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "camera/synthetic_scene.h"
#include "storage/scene/scene.h"

namespace rockface::app {

struct SyntheticSceneInput {
  camera::SyntheticScene scene;                      // datum-relative coordinates; the first pair
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // add to get absolute coordinates
  // Every stereo pair of the visit (imaging.stations in pairs), the first
  // one being scene.stations; datum-relative.
  std::vector<std::array<camera::SyntheticStation, 2>> pairs;
};

// Throws InputError naming the scene file when it has no imaging section
// or no surface to photograph.
SyntheticSceneInput synthetic_scene_from_scene(const storage::Scene& scene);

}  // namespace rockface::app
