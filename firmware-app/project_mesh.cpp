#include "firmware-app/project_mesh.h"

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

}  // namespace rockface::app
