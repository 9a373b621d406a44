#pragma once
// Reading a PLY mesh a user gives (a 3D image exported by rockface, or one
// from MeshLab, CloudCompare, Metashape): ascii, binary_little_endian or
// binary_big_endian; the vertex element's x, y, z (any numeric type),
// optional red, green, blue (uchar) and texture_u, texture_v (or s, t or
// u, v); the face element's vertex_indices (or vertex_index) list, polygons
// fanned into triangles. Other elements and properties are skipped.
//
// Coordinates come back relative to a datum, so survey coordinates of 10^6 m
// keep their millimetres in the mesh: the datum the one PLY writer
// (ply_writer.h) names in its frame comment, else the first vertex rounded
// to metres when coordinates are that large (beyond 10 km), else zero.
//
// Everything is checked: a header that does not describe the data, element
// counts larger than the file holds, non-finite coordinates, indices outside
// the vertices, degenerate faces. Errors are InputError naming the file and
// the place ("model.ply: vertex 12: x is not a finite number").
#include <filesystem>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "storage/project/project_records.h"

namespace rockface::storage {

struct PlyModel {
  Mesh mesh;  // vertices relative to `datum`; faces are triangles
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();  // absolute = mesh vertex + datum
  std::string texture_file;                         // "comment TextureFile ..." when present
};

// `bytes` is the whole file; `source` names it in errors.
PlyModel parse_ply(std::string_view bytes, const std::string& source);
PlyModel read_ply_mesh(const std::filesystem::path& file);

}  // namespace rockface::storage
