#pragma once
// The effects a scene lists, as the modules that act on single blocks in
// limit equilibrium (gravity always): one composition for explicit blocks
// and blocks from traces.
#include "core/analysis/analysis_input.h"
#include "core/kinematics/effects/effect.h"

namespace rockface::analysis {

// Throws InputError naming the scene file and the effect's field.
kinematics::Effects scene_effects(const AnalysisInput& scene);

}  // namespace rockface::analysis
