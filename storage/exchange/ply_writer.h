#pragma once
// The one PLY writer (CloudCompare, MeshLab and Blender read it): vertices
// with colour (red, green, blue) and texture coordinates (texture_u,
// texture_v; v up as PLY viewers expect) when the mesh has them, and
// triangles as vertex_indices. Used for the reconstruction's 3D image and
// for models exported from a project; each passes a view of its own mesh
// type, so nothing is copied (a precise 24 Mpx model has 5 M vertices).
//
// Coordinates are absolute survey coordinates by default (datum added back,
// written as double so that 10^6 m keeps its millimetres); relative ones are
// written as float, which is exact to ~0.01 mm within 100 m of the datum.
#include <array>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

#include <Eigen/Core>

namespace rockface::storage {

struct PlyOptions {
  bool binary = true;        // binary_little_endian, else ascii
  bool absolute = true;      // add the datum back (double); else datum-relative (float)
  std::string texture_file;  // written as "comment TextureFile ..." when not empty
  std::string comment;       // one line about where the model comes from
  bool with_faces = true;    // false: the vertices alone (a point cloud)
};

struct PlyMeshView {
  std::size_t vertices = 0;
  std::function<Eigen::Vector3d(std::size_t)> position;            // datum-relative
  std::function<std::array<std::uint8_t, 3>(std::size_t)> colour;  // empty: no colours
  std::function<Eigen::Vector2f(std::size_t)> texcoord;            // (u, v up); empty: none
  std::size_t triangles = 0;
  std::function<std::array<int, 3>(std::size_t)> triangle;
};

void write_ply_mesh(std::ostream& out, const PlyMeshView& mesh, const Eigen::Vector3d& datum,
                    const PlyOptions& options);

}  // namespace rockface::storage
