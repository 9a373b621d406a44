#pragma once
// A parsed scene file (storage/scene/scene.h) as the analysis input
// (core/analysis/analysis_input.h), once, at the boundary: the scene's
// imaging and picks are left aside, its tunnel gives a falling block's floor.
#include "core/analysis/analysis_input.h"
#include "storage/scene/scene.h"

namespace rockface::app {

// The analysis input of a parsed scene (its imaging and picks left aside).
analysis::AnalysisInput analysis_input(const storage::Scene& scene);

// The invert of the scene's tunnel at its face as the floor a falling block
// lands on (analysis.dynamics without a floor): the design profile's lowest
// point, in the plane of the cross-section's right and the drive.
analysis::SceneFloor tunnel_invert_floor(const storage::Scene& scene);

}  // namespace rockface::app
