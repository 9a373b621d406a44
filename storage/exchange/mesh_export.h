#pragma once
// Writing the "3D image" (photogrammetry::SurfaceMesh) for other programs:
// binary PLY (points with colour, texture coordinates and the lattice
// triangles; MeshLab/CloudCompare read it) and Wavefront OBJ with a material
// that uses the left photograph as texture. Coordinates are written absolute
// (datum added) in double precision, so survey coordinates keep their
// millimetres.
#include <filesystem>
#include <string>

#include <Eigen/Core>

#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::storage {

struct MeshExportOptions {
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();  // added to every vertex
  std::string texture_file;  // the left photograph, as referred to from the output; may be empty
  bool with_faces = true;    // false: a point cloud only
};

// Throws rockface::Error naming the file when it cannot be written.
void write_ply(const std::filesystem::path& path, const photogrammetry::SurfaceMesh& mesh,
               const MeshExportOptions& options = {});

// Writes `path` (.obj) and, with a texture file, a material file beside it
// (same stem, .mtl).
void write_obj(const std::filesystem::path& path, const photogrammetry::SurfaceMesh& mesh,
               const MeshExportOptions& options = {});

}  // namespace rockface::storage
