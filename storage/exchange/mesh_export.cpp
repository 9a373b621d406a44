#include "storage/exchange/mesh_export.h"

#include <cstdint>
#include <cstdio>

#include "core/common/atomic_file.h"
#include "storage/exchange/ply_writer.h"

namespace rockface::storage {

void write_ply(const std::filesystem::path& path, const photogrammetry::SurfaceMesh& mesh,
               const MeshExportOptions& o) {
  PlyMeshView view;
  view.vertices = mesh.size();
  view.position = [&](std::size_t i) { return mesh.vertices[i]; };
  if (mesh.colours.size() == mesh.size())
    view.colour = [&](std::size_t i) { return mesh.colours[i]; };
  if (mesh.texcoords.size() == mesh.size())
    view.texcoord = [&](std::size_t i) { return mesh.texcoords[i]; };  // already v up
  view.triangles = o.with_faces ? mesh.triangles.size() : 0;
  view.triangle = [&](std::size_t f) { return mesh.triangles[f]; };
  PlyOptions options;
  options.texture_file = o.texture_file;
  options.comment = "rockface 3D image";
  write_file_atomically(path,
                        [&](std::ostream& out) { write_ply_mesh(out, view, o.datum, options); });
}

void write_obj(const std::filesystem::path& path, const photogrammetry::SurfaceMesh& mesh,
               const MeshExportOptions& o) {
  write_file_atomically(path, [&](std::ostream& out) {
    const bool uv = mesh.texcoords.size() == mesh.size();
    out << "# rockface 3D image: x East, y North, z Up\n";
    if (!o.texture_file.empty()) {
      std::filesystem::path mtl = path;
      mtl.replace_extension(".mtl");
      write_text_atomically(mtl,
                            "newmtl photo\nKa 1 1 1\nKd 1 1 1\nmap_Kd " + o.texture_file + "\n");
      out << "mtllib " << mtl.filename().string() << "\nusemtl photo\n";
    }
    char line[160];
    for (std::size_t i = 0; i < mesh.size(); ++i) {
      const Eigen::Vector3d p = mesh.vertices[i] + o.datum;
      const auto& c =
          i < mesh.colours.size() ? mesh.colours[i] : std::array<std::uint8_t, 3>{128, 128, 128};
      // Vertex colours as the common "v x y z r g b" extension.
      std::snprintf(line, sizeof line, "v %.4f %.4f %.4f %.4f %.4f %.4f\n", p.x(), p.y(), p.z(),
                    c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
      out << line;
    }
    if (uv)
      for (const auto& t : mesh.texcoords) {
        std::snprintf(line, sizeof line, "vt %.6f %.6f\n", t.x(), t.y());
        out << line;
      }
    if (o.with_faces)
      for (const auto& f : mesh.triangles) {
        if (uv)
          out << "f " << f[0] + 1 << '/' << f[0] + 1 << ' ' << f[1] + 1 << '/' << f[1] + 1 << ' '
              << f[2] + 1 << '/' << f[2] + 1 << '\n';
        else
          out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
      }
  });
}

}  // namespace rockface::storage
