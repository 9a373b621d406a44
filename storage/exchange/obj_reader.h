#pragma once
// Reading a Wavefront OBJ mesh (Metashape, Pix4D, RealityCapture, OpenMVS,
// MeshLab exports) with tinyobjloader (Debian's libtinyobjloader-dev, its
// double-precision build, so that survey coordinates keep their
// millimetres): vertices, faces (polygons fanned into triangles), vertex
// colours ("v x y z r g b"), texture coordinates and the first material's
// diffuse texture (map_Kd of its MTL). A vertex used with several texture
// coordinates becomes one vertex per coordinate, as the project's mesh keeps
// one texture coordinate a vertex. An OBJ of vertices without faces is a
// point cloud.
//
// Checked after the library: indices inside the vertices and texture
// coordinates, finite coordinates, a texture file that exists.
#include <filesystem>
#include <string>
#include <string_view>

#include "storage/exchange/imported_surface.h"

namespace rockface::storage {

// `bytes` is the OBJ; its MTL files are looked for in `material_dir` (none:
// materials are not read); `source` names the file in errors.
ImportedSurface parse_obj(std::string_view bytes, const std::string& source,
                          const std::filesystem::path& material_dir);

ImportedSurface read_obj(const std::filesystem::path& file);

}  // namespace rockface::storage
