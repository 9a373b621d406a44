#pragma once
// The scene's `wedges` section (docs/scene-extensions.md) read into the
// wedge analysis's values (core/analysis/wedges_input.h).
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/analysis/wedges_input.h"

namespace rockface::storage {

class Reader;

// Reads `wedges`; a profile file named in it is relative to the scene file.
analysis::SceneWedges read_scene_wedges(const Reader& r, const nlohmann::json& section,
                                        const std::string& scene_path);

}  // namespace rockface::storage
