#pragma once
// The scene's `effects` section (SCENE.md) read into the analysis input's
// values (core/analysis/analysis_input.h): the JSON's shape (types, required
// and unknown fields, a 3x3 tensor); the values' ranges are checked by
// analysis::check_analysis_input. Also what a project's analysis run stores
// as its effects (AnalysisRun::effects_json), read back for the tablet.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/analysis/analysis_input.h"

namespace rockface::storage {

class Reader;

// Reads `section`, the scene's "effects" object, naming fields "effects.*".
analysis::SceneEffects read_scene_effects(const Reader& r, const nlohmann::json& section);

}  // namespace rockface::storage
