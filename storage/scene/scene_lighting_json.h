#pragma once
// Reads the tunnel lighting fields of `imaging.effects` (flash, lamps,
// vignetting, sensor, jpeg_quality, wet, shotcrete, dust;
// docs/scene-extensions.md) into the scene's imaging effects.
#include <string>

#include <nlohmann/json.hpp>

#include "storage/json_reader.h"
#include "storage/scene/scene.h"

namespace rockface::storage {

// `effects` is the imaging.effects object, `path` its field path. Throws
// InputError naming the field for a bad value.
void read_tunnel_lighting(const Reader& r, const nlohmann::json& effects, const std::string& path,
                          SceneImagingEffects& out);

}  // namespace rockface::storage
