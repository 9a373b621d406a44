#include "firmware-app/records/project_mesh.h"

namespace rockface::app {

storage::Mesh project_mesh(const photogrammetry::SurfaceMesh& m) {
  storage::Mesh out;
  out.vertices = m.vertices;
  out.faces.reserve(m.triangles.size());
  for (const auto& t : m.triangles) out.faces.push_back({t[0], t[1], t[2]});
  out.texcoords.reserve(m.texcoords.size());
  for (const auto& t : m.texcoords) out.texcoords.push_back({t.x(), t.y()});
  out.colours = m.colours;
  return out;
}

photogrammetry::SurfaceMesh surface_mesh(storage::Mesh&& m, int texture_width, int texture_height) {
  photogrammetry::SurfaceMesh s;
  s.vertices = std::move(m.vertices);
  s.triangles.reserve(m.faces.size());
  for (const auto& f : m.faces) s.triangles.push_back({f[0], f[1], f[2]});
  s.colours = std::move(m.colours);
  s.texture_width = texture_width;
  s.texture_height = texture_height;
  if (m.texcoords.size() == s.vertices.size() && texture_width > 0 && texture_height > 0) {
    s.texcoords.reserve(m.texcoords.size());
    for (const auto& t : m.texcoords) s.texcoords.emplace_back(t[0], t[1]);
    s.pixels_from_texcoords(texture_width, texture_height);
  }
  return s;
}

}  // namespace rockface::app
