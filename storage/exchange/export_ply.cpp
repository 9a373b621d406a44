#include "storage/exchange/export_ply.h"

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "storage/project/project_store.h"

namespace rockface::storage {

void write_model_ply(std::ostream& out, const Mesh& mesh, const Eigen::Vector3d& datum,
                     const PlyOptions& options) {
  PlyMeshView view;
  view.vertices = mesh.vertices.size();
  view.position = [&](std::size_t i) { return mesh.vertices[i]; };
  if (!mesh.colours.empty() && mesh.colours.size() == mesh.vertices.size())
    view.colour = [&](std::size_t i) { return mesh.colours[i]; };
  // Stored texture coordinates have v down (image rows); PLY viewers want v up.
  if (!mesh.texcoords.empty() && mesh.texcoords.size() == mesh.vertices.size())
    view.texcoord = [&](std::size_t i) {
      return Eigen::Vector2f(mesh.texcoords[i][0], 1.0f - mesh.texcoords[i][1]);
    };
  view.triangles = mesh.faces.size();
  view.triangle = [&](std::size_t f) {
    return std::array<int, 3>{mesh.faces[f][0], mesh.faces[f][1], mesh.faces[f][2]};
  };
  write_ply_mesh(out, view, datum, options);
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
