#pragma once
// A stored model as PLY through the one PLY writer (storage/exchange/ply_writer.h).
#include <filesystem>
#include <ostream>
#include <string>

#include "storage/exchange/ply_writer.h"
#include "storage/project/project_records.h"

namespace rockface::storage {

class ProjectStore;

void write_model_ply(std::ostream& out, const Mesh& mesh, const Eigen::Vector3d& datum,
                     const PlyOptions& options);

// Model `model_id` to `file`. When the model has texture coordinates and a
// texture capture, the texture image is written beside it
// (<stem>-texture.jpg or .png) and named in the PLY. Logs the export when the
// project is writable.
void export_model_ply(ProjectStore& store, RecordId model_id, const std::filesystem::path& file,
                      PlyOptions options = {});

}  // namespace rockface::storage
