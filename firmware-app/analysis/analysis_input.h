#pragma once
// What the block analysis takes, as values: the planes (joints, then free
// faces: a block code has one digit per plane in this order), the scene's
// explicit blocks, the free surface and the traces on it, the rock, the
// effects and the analysis options. Angles in degrees and points absolute,
// as in the scene file. The replay fills it with the measured joint planes
// and traces; a scene file becomes one once, at the boundary
// (analysis_input).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "storage/scene.h"

namespace rockface::app {

struct AnalysisInput {
  std::string source;  // names the input in messages (a scene file, a project's visit)
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  bool has_datum = false;
  double density = 2700;  // kg/m^3
  Eigen::Vector3d gravity{0, 0, -9.81};
  std::vector<analysis::SceneJoint> joints;
  std::vector<analysis::SceneFreeFace> free_faces;
  std::vector<analysis::SceneBlock> blocks;
  std::vector<analysis::ScenePatch> patches;
  std::vector<analysis::SceneTrace> traces;
  analysis::SceneAnalysis analysis;
  analysis::SceneEffects effects;
  // The rock-mass form the scene brings (its `rockmass` section), for the
  // report's rock-mass section.
  std::optional<rockmass::ClassificationForm> rockmass_form;

  const analysis::SceneJoint* joint(const std::string& id) const;
  // Index of a plane id among joints followed by free faces, -1 if unknown.
  int plane_index(const std::string& id) const;
};

// The analysis input of a parsed scene (its imaging and picks left aside).
AnalysisInput analysis_input(const storage::Scene& scene);

// The invert of the scene's tunnel at its face as the floor a falling block
// lands on (analysis.dynamics without a floor): the design profile's lowest
// point, in the plane of the cross-section's right and the drive.
analysis::SceneFloor tunnel_invert_floor(const storage::Scene& scene);

}  // namespace rockface::app
