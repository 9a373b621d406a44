#include "storage/exchange/export_obj.h"

#include <cstdio>

#include "core/common/atomic_file.h"
#include "storage/exchange/model_texture.h"
#include "storage/project/project_store.h"

namespace rockface::storage {

void write_model_obj(std::ostream& out, const Mesh& mesh, const Eigen::Vector3d& datum,
                     const std::string& material_file) {
  char line[200];
  out << "# rockface 3D image: x East, y North, z Up, metres\n";
  std::snprintf(line, sizeof line, "# datum (added to every vertex): %.4f %.4f %.4f\n", datum.x(),
                datum.y(), datum.z());
  out << line;
  if (!material_file.empty()) out << "mtllib " << material_file << "\nusemtl photo\n";
  const bool colours = mesh.colours.size() == mesh.vertices.size();
  const bool uv = mesh.texcoords.size() == mesh.vertices.size();
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d p = mesh.vertices[i] + datum;
    if (colours) {
      const auto& c = mesh.colours[i];
      std::snprintf(line, sizeof line, "v %.4f %.4f %.4f %.4f %.4f %.4f\n", p.x(), p.y(), p.z(),
                    c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    } else {
      std::snprintf(line, sizeof line, "v %.4f %.4f %.4f\n", p.x(), p.y(), p.z());
    }
    out << line;
  }
  // Stored texture coordinates have v down (image rows); OBJ's v is up.
  if (uv)
    for (const auto& t : mesh.texcoords) {
      std::snprintf(line, sizeof line, "vt %.6f %.6f\n", t[0], 1.0 - t[1]);
      out << line;
    }
  for (const auto& f : mesh.faces) {
    if (uv)
      std::snprintf(line, sizeof line, "f %d/%d %d/%d %d/%d\n", f[0] + 1, f[0] + 1, f[1] + 1,
                    f[1] + 1, f[2] + 1, f[2] + 1);
    else
      std::snprintf(line, sizeof line, "f %d %d %d\n", f[0] + 1, f[1] + 1, f[2] + 1);
    out << line;
  }
}

void export_model_obj(ProjectStore& store, RecordId model_id, const std::filesystem::path& file) {
  const Model model = store.load_model(model_id);
  const ProjectInfo project = store.project();
  std::string material;
  if (const std::string texture = write_model_texture(store, model, file); !texture.empty()) {
    std::filesystem::path mtl = file;
    mtl.replace_extension(".mtl");
    write_text_atomically(
        mtl, "newmtl photo\nKa 1 1 1\nKd 1 1 1\nd 1\nillum 1\nmap_Kd " + texture + "\n");
    material = mtl.filename().string();
  }
  write_file_atomically(
      file, [&](std::ostream& out) { write_model_obj(out, model.mesh, project.datum, material); });
  if (!store.read_only())
    store.log_action(std::nullopt, "export model obj",
                     "model " + std::to_string(model_id) + " to " + file.string());
}

}  // namespace rockface::storage
