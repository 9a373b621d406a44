#pragma once
// Reads a PLY mesh back: what storage/ply_writer.h writes (the
// reconstruction's MODEL.ply, a model exported from a project), ascii or
// binary_little_endian, vertex x, y, z (float or double), optional colour
// (red, green, blue) and texture coordinates (texture_u, texture_v), faces as
// triangles. Other vertex properties are skipped.
#include <filesystem>
#include <string>

#include <Eigen/Core>

#include "storage/project_records.h"

namespace rockface::storage {

struct PlyModel {
  Mesh mesh;  // vertices relative to `datum`
  // The datum the writer named in its frame comment ("datum X Y Z added");
  // zero when there is none.
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  std::string texture_file;  // "comment TextureFile ..."; empty when none
};

// Throws InputError naming the file (and the header line or element) for a
// file that is not such a PLY, is cut short, or has a face that is not a
// triangle or names a vertex that does not exist.
PlyModel read_ply_mesh(const std::filesystem::path& file);

}  // namespace rockface::storage
