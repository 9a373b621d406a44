#include "storage/exchange/export_ply.h"

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "storage/exchange/model_texture.h"
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
  view.triangles = options.with_faces ? mesh.faces.size() : 0;
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
  // A point cloud has no faces to texture: its vertices carry their colours.
  if (options.with_faces)
    if (const std::string texture = write_model_texture(store, model, file); !texture.empty())
      options.texture_file = texture;
  write_file_atomically(
      file, [&](std::ostream& out) { write_model_ply(out, model.mesh, project.datum, options); });
  if (!store.read_only())
    store.log_action(std::nullopt, "export model ply",
                     "model " + std::to_string(model_id) + " to " + file.string());
}

}  // namespace rockface::storage
