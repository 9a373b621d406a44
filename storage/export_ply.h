#pragma once
// A stored model as PLY (readable by CloudCompare, MeshLab, Blender):
// vertices with colour (red, green, blue) and texture coordinates
// (texture_u, texture_v; v up as PLY viewers expect) when the model has them,
// and triangles as vertex_indices.
//
// Coordinates are absolute survey coordinates by default (datum added back,
// written as double so that 10^6 m keeps its millimetres); relative ones are
// written as float, which is exact to ~0.01 mm within 100 m of the datum.
#include <filesystem>
#include <ostream>
#include <string>

#include "storage/project_records.h"

namespace rockface::storage {

class ProjectStore;

struct PlyOptions {
  bool binary = true;        // binary_little_endian, else ascii
  bool absolute = true;      // add the datum back (double); else datum-relative (float)
  std::string texture_file;  // written as "comment TextureFile ..." when not empty
  std::string comment;       // one line about where the model comes from
};

void write_model_ply(std::ostream& out, const Mesh& mesh, const Eigen::Vector3d& datum,
               const PlyOptions& options);

// Model `model_id` to `file`. When the model has texture coordinates and a
// texture capture, the texture image is written beside it
// (<stem>-texture.jpg or .png) and named in the PLY. Logs the export when the
// project is writable.
void export_model_ply(ProjectStore& store, RecordId model_id, const std::filesystem::path& file,
                      PlyOptions options = {});

}  // namespace rockface::storage
