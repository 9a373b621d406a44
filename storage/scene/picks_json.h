#pragma once
// The reader of the picks (core/measure/picks.h), format rockface-picks/1
// (docs/scene-extensions.md): a PICKS file for `rockface measure`, and a
// scene's `picks` for `rockface replay`.
#include <string>

#include <nlohmann/json.hpp>

#include "core/measure/picks.h"

namespace rockface::storage {

// Reads the picks object at `path` of a document ("" for a PICKS file, whose
// `format` must be rockface-picks/1; "picks" inside a scene). Every rejection
// is an InputError naming `source`, the field path and the reason: ids
// unique over traces, areas and points; photo "left" or "right"; pair a
// count from 1, a further pair's photograph its left one; a trace with at
// least two distinct picks; finite numbers.
measure::Picks read_picks(const nlohmann::json& object, const std::string& source,
                          const std::string& path);

// PICKS text (`source` names it in messages), and a PICKS file.
measure::Picks parse_picks(const std::string& text, const std::string& source);
measure::Picks load_picks(const std::string& file);

}  // namespace rockface::storage
