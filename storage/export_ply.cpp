#include "storage/export_ply.h"

#include <bit>
#include <cstdio>

#include "core/common/error.h"
#include "storage/export_file.h"
#include "storage/project_store.h"

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

void write_model_ply(std::ostream& out, const Mesh& mesh, const Eigen::Vector3d& datum,
               const PlyOptions& options) {
  const bool colours = !mesh.colours.empty() && mesh.colours.size() == mesh.vertices.size();
  const bool texcoords = !mesh.texcoords.empty() && mesh.texcoords.size() == mesh.vertices.size();
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
  out << "element vertex " << mesh.vertices.size() << '\n'
      << "property " << coord_type << " x\n"
      << "property " << coord_type << " y\n"
      << "property " << coord_type << " z\n";
  if (colours) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (texcoords) out << "property float texture_u\nproperty float texture_v\n";
  out << "element face " << mesh.faces.size() << '\n'
      << "property list uchar int vertex_indices\n"
      << "end_header\n";

  const Eigen::Vector3d offset = options.absolute ? datum : Eigen::Vector3d::Zero();
  if (options.binary) {
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Eigen::Vector3d p = offset + mesh.vertices[i];
      for (int k = 0; k < 3; ++k) {
        if (options.absolute)
          put<double>(out, p[k]);
        else
          put<float>(out, static_cast<float>(p[k]));
      }
      if (colours)
        for (std::uint8_t c : mesh.colours[i]) put<std::uint8_t>(out, c);
      if (texcoords) {
        put<float>(out, mesh.texcoords[i][0]);
        put<float>(out, 1.0f - mesh.texcoords[i][1]);
      }
    }
    for (const auto& f : mesh.faces) {
      put<std::uint8_t>(out, 3);
      for (std::int32_t v : f) put<std::int32_t>(out, v);
    }
    return;
  }
  char text[160];
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d p = offset + mesh.vertices[i];
    // %.4f: 0.1 mm, below any photogrammetric precision at the face.
    std::snprintf(text, sizeof(text), "%.4f %.4f %.4f", p.x(), p.y(), p.z());
    out << text;
    if (colours)
      out << ' ' << int{mesh.colours[i][0]} << ' ' << int{mesh.colours[i][1]} << ' '
          << int{mesh.colours[i][2]};
    if (texcoords) {
      std::snprintf(text, sizeof(text), " %.6f %.6f", mesh.texcoords[i][0],
                    1.0 - mesh.texcoords[i][1]);
      out << text;
    }
    out << '\n';
  }
  for (const auto& f : mesh.faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
}

void export_model_ply(ProjectStore& store, RecordId model_id, const std::filesystem::path& file,
                      PlyOptions options) {
  const Model model = store.load_model(model_id);
  const ProjectInfo project = store.project();
  if (options.comment.empty())
    options.comment = "rockface model " + std::to_string(model_id) + " of project " + project.name;
  if (model.texture_capture_id && !model.mesh.texcoords.empty()) {
    const ImageBlob image = store.load_capture_image(*model.texture_capture_id, model.texture_side);
    std::filesystem::path texture = file;
    texture.replace_filename(file.stem().string() + "-texture" +
                             (image.format == "png" ? ".png" : ".jpg"));
    write_file_atomically(texture, [&](std::ostream& out) {
      out.write(reinterpret_cast<const char*>(image.bytes.data()),
                static_cast<std::streamsize>(image.bytes.size()));
    });
    options.texture_file = texture.filename().string();
  }
  write_file_atomically(
      file, [&](std::ostream& out) { write_model_ply(out, model.mesh, project.datum, options); });
  if (!store.read_only())
    store.log_action(std::nullopt, "export model ply",
                     "model " + std::to_string(model_id) + " to " + file.string());
}

}  // namespace rockface::storage
