#pragma once
// A stored model as Wavefront OBJ with its material and texture (what
// CloudCompare, MeshLab, Blender and AutoCAD's 3D import open): vertices
// absolute in the project's frame (survey coordinates where the project has
// them: the datum added back and written with 0.1 mm), vertex colours as the
// common "v x y z r g b" extension, texture coordinates with v up, and the
// datum named in a comment (OBJ has no place of its own for an offset).
#include <filesystem>
#include <ostream>
#include <string>

#include <Eigen/Core>

#include "storage/project/project_records.h"

namespace rockface::storage {

class ProjectStore;

// `material_file` (may be empty): the .mtl the OBJ refers to, whose one
// material "photo" is used by every face.
void write_model_obj(std::ostream& out, const Mesh& mesh, const Eigen::Vector3d& datum,
                     const std::string& material_file);

// Model `model_id` to `file` (.obj), with <stem>.mtl and the texture
// (<stem>-texture.jpg) beside it when the model has one. Logs the export
// when the project is writable.
void export_model_obj(ProjectStore& store, RecordId model_id, const std::filesystem::path& file);

}  // namespace rockface::storage
