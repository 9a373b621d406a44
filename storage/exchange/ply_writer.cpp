#include "storage/exchange/ply_writer.h"

#include <bit>
#include <cstdio>

namespace rockface::storage {

static_assert(std::endian::native == std::endian::little,
              "binary PLY is written as binary_little_endian from native values");

namespace {

template <typename T>
void put(std::ostream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

void write_ply_mesh(std::ostream& out, const PlyMeshView& mesh, const Eigen::Vector3d& datum,
                    const PlyOptions& options) {
  const bool colours = static_cast<bool>(mesh.colour);
  const bool texcoords = static_cast<bool>(mesh.texcoord);
  const char* coord_type = options.absolute ? "double" : "float";
  out << "ply\n"
      << "format " << (options.binary ? "binary_little_endian" : "ascii") << " 1.0\n";
  if (!options.comment.empty()) out << "comment " << one_line(options.comment) << '\n';
  char datum_text[128];
  std::snprintf(datum_text, sizeof(datum_text), "%.4f %.4f %.4f", datum.x(), datum.y(), datum.z());
  out << "comment frame x East, y North, z Up, metres; "
      << (options.absolute ? "absolute (datum " : "relative to datum ") << datum_text
      << (options.absolute ? " added)" : "") << '\n';
  if (!options.texture_file.empty() && texcoords)
    out << "comment TextureFile " << one_line(options.texture_file) << '\n';
  out << "element vertex " << mesh.vertices << '\n'
      << "property " << coord_type << " x\n"
      << "property " << coord_type << " y\n"
      << "property " << coord_type << " z\n";
  if (colours) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (texcoords) out << "property float texture_u\nproperty float texture_v\n";
  out << "element face " << mesh.triangles << '\n'
      << "property list uchar int vertex_indices\n"
      << "end_header\n";

  const Eigen::Vector3d offset = options.absolute ? datum : Eigen::Vector3d::Zero();
  if (options.binary) {
    for (std::size_t i = 0; i < mesh.vertices; ++i) {
      const Eigen::Vector3d p = offset + mesh.position(i);
      for (int k = 0; k < 3; ++k) {
        if (options.absolute)
          put<double>(out, p[k]);
        else
          put<float>(out, static_cast<float>(p[k]));
      }
      if (colours)
        for (std::uint8_t c : mesh.colour(i)) put<std::uint8_t>(out, c);
      if (texcoords) {
        const Eigen::Vector2f t = mesh.texcoord(i);
        put<float>(out, t.x());
        put<float>(out, t.y());
      }
    }
    for (std::size_t f = 0; f < mesh.triangles; ++f) {
      put<std::uint8_t>(out, 3);
      for (int v : mesh.triangle(f)) put<std::int32_t>(out, v);
    }
    return;
  }
  char text[160];
  for (std::size_t i = 0; i < mesh.vertices; ++i) {
    const Eigen::Vector3d p = offset + mesh.position(i);
    // %.4f: 0.1 mm, below any photogrammetric precision at the face.
    std::snprintf(text, sizeof(text), "%.4f %.4f %.4f", p.x(), p.y(), p.z());
    out << text;
    if (colours) {
      const auto c = mesh.colour(i);
      out << ' ' << int{c[0]} << ' ' << int{c[1]} << ' ' << int{c[2]};
    }
    if (texcoords) {
      const Eigen::Vector2f t = mesh.texcoord(i);
      std::snprintf(text, sizeof(text), " %.6f %.6f", t.x(), t.y());
      out << text;
    }
    out << '\n';
  }
  for (std::size_t f = 0; f < mesh.triangles; ++f) {
    const auto t = mesh.triangle(f);
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
}

}  // namespace rockface::storage
