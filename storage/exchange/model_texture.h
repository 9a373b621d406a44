#pragma once
// The photograph a stored model is textured with, written beside an export
// of it (<stem>-texture.jpg or .png): PLY and OBJ name it the same way.
#include <filesystem>
#include <string>

#include "storage/project/project_records.h"

namespace rockface::storage {

class ProjectStore;

// Writes the texture of `model` beside `file` and returns its file name (as
// the export names it, relative to the export's folder); empty when the
// model has no texture coordinates or no texture photograph.
std::string write_model_texture(ProjectStore& store, const Model& model,
                                const std::filesystem::path& file);

}  // namespace rockface::storage
