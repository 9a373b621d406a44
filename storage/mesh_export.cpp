#include "storage/mesh_export.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <fstream>

#include "core/common/error.h"

namespace rockface::storage {

namespace {

static_assert(std::endian::native == std::endian::little, "PLY is written as binary_little_endian");

template <typename T>
void put(std::ofstream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

void check(const std::ofstream& out, const std::filesystem::path& path) {
  if (!out) throw Error(path.string() + ": cannot write the file (disk full or no permission?)");
}

// Writes through `path.part` and renames, so a failed write never leaves a
// truncated model in place of a good one.
template <typename Write>
void write_atomically(const std::filesystem::path& path, bool binary, Write write) {
  std::filesystem::path tmp = path;
  tmp += ".part";
  try {
    {
      std::ofstream out(tmp, (binary ? std::ios::binary : std::ios::openmode{}) | std::ios::trunc);
      check(out, path);
      write(out);
      out.flush();
      check(out, path);
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw Error(path.string() + ": cannot write the file (" + ec.message() + ")");
  } catch (...) {
    std::error_code ignore;
    std::filesystem::remove(tmp, ignore);
    throw;
  }
}

}  // namespace

void write_ply(const std::filesystem::path& path, const photogrammetry::SurfaceMesh& mesh,
               const MeshExportOptions& o) {
  write_atomically(path, true, [&](std::ofstream& out) {
    const bool uv = mesh.texcoords.size() == mesh.size();
    const std::size_t faces = o.with_faces ? mesh.triangles.size() : 0;
    out << "ply\nformat binary_little_endian 1.0\n"
        << "comment rockface 3D image: x East, y North, z Up\n";
    if (!o.texture_file.empty()) out << "comment TextureFile " << o.texture_file << "\n";
    out << "element vertex " << mesh.size() << "\n"
        << "property double x\nproperty double y\nproperty double z\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (uv) out << "property float texture_u\nproperty float texture_v\n";
    out << "element face " << faces << "\n"
        << "property list uchar int vertex_indices\n"
        << "end_header\n";
    for (std::size_t i = 0; i < mesh.size(); ++i) {
      const Eigen::Vector3d p = mesh.vertices[i] + o.datum;
      put(out, p.x());
      put(out, p.y());
      put(out, p.z());
      const auto& c =
          i < mesh.colours.size() ? mesh.colours[i] : std::array<std::uint8_t, 3>{128, 128, 128};
      put(out, c[0]);
      put(out, c[1]);
      put(out, c[2]);
      if (uv) {
        put(out, mesh.texcoords[i].x());
        put(out, mesh.texcoords[i].y());
      }
    }
    for (std::size_t f = 0; f < faces; ++f) {
      put(out, static_cast<std::uint8_t>(3));
      for (int k = 0; k < 3; ++k) put(out, static_cast<std::int32_t>(mesh.triangles[f][k]));
    }
  });
}

void write_obj(const std::filesystem::path& path, const photogrammetry::SurfaceMesh& mesh,
               const MeshExportOptions& o) {
  write_atomically(path, false, [&](std::ofstream& out) {
    const bool uv = mesh.texcoords.size() == mesh.size();
    out << "# rockface 3D image: x East, y North, z Up\n";
    if (!o.texture_file.empty()) {
      std::filesystem::path mtl = path;
      mtl.replace_extension(".mtl");
      std::ofstream m(mtl, std::ios::trunc);
      m << "newmtl photo\nKa 1 1 1\nKd 1 1 1\nmap_Kd " << o.texture_file << "\n";
      m.flush();
      check(m, mtl);
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
