#include "ui/view3d/display_mesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <Eigen/Geometry>

namespace rockface::ui {

namespace {

// Vertex clustering on a grid of `cell` metres: every vertex is replaced by
// the first vertex of its cell; triangles whose corners fall in fewer than
// three cells vanish.
std::vector<std::int32_t> cluster(const storage::Mesh& mesh, double cell,
                                  const Eigen::Vector3d& low) {
  std::unordered_map<std::int64_t, std::int32_t> first;
  std::vector<std::int32_t> representative(mesh.vertices.size());
  constexpr std::int64_t kCells = 1 << 20;  // per axis: the key packs three 20-bit indices
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d c = ((mesh.vertices[i] - low) / cell).array().floor();
    const std::int64_t key =
        (static_cast<std::int64_t>(c.x()) * kCells + static_cast<std::int64_t>(c.y())) * kCells +
        static_cast<std::int64_t>(c.z());
    representative[i] = first.try_emplace(key, static_cast<std::int32_t>(i)).first->second;
  }
  return representative;
}

}  // namespace

DisplayMesh make_display_mesh(const storage::Mesh& mesh, std::size_t max_triangles) {
  DisplayMesh out;
  if (mesh.vertices.empty()) return out;
  Eigen::AlignedBox3d box;
  for (const auto& v : mesh.vertices) box.extend(v);
  out.centre = box.center();
  out.radius = box.diagonal().norm() / 2;

  std::vector<std::array<std::int32_t, 3>> faces = mesh.faces;
  if (max_triangles > 0 && faces.size() > max_triangles) {
    // A surface of n vertices on a grid cell c has about area / c^2 cells,
    // so halving the triangles takes a cell sqrt(2) larger; start from the
    // ratio and grow until under budget.
    double cell = box.diagonal().norm() / std::sqrt(static_cast<double>(max_triangles)) * 0.5;
    for (;;) {
      const std::vector<std::int32_t> rep = cluster(mesh, cell, box.min());
      faces.clear();
      for (const auto& f : mesh.faces) {
        const std::array<std::int32_t, 3> g{rep[f[0]], rep[f[1]], rep[f[2]]};
        if (g[0] != g[1] && g[1] != g[2] && g[0] != g[2]) faces.push_back(g);
      }
      out.cell = cell;
      if (faces.size() <= max_triangles) break;
      cell *= std::sqrt(2.0);
    }
  }

  // Compact the vertices the kept faces use.
  std::vector<std::int32_t> index(mesh.vertices.size(), -1);
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  const bool textured = mesh.texcoords.size() == mesh.vertices.size();
  const bool coloured = mesh.colours.size() == mesh.vertices.size();
  for (const auto& f : faces) {
    const Eigen::Vector3d& a = mesh.vertices[f[0]];
    normal_sum += (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a);
    for (const std::int32_t v : f) {
      if (index[v] < 0) {
        index[v] = static_cast<std::int32_t>(out.positions.size() / 3);
        const Eigen::Vector3f p = (mesh.vertices[v] - out.centre).cast<float>();
        out.positions.insert(out.positions.end(), {p.x(), p.y(), p.z()});
        if (textured)
          out.texcoords.insert(out.texcoords.end(), {mesh.texcoords[v][0], mesh.texcoords[v][1]});
        if (coloured)
          out.colours.insert(out.colours.end(), mesh.colours[v].begin(), mesh.colours[v].end());
      }
      out.indices.push_back(static_cast<std::uint32_t>(index[v]));
    }
  }
  if (normal_sum.norm() > 0) out.mean_normal = normal_sum.normalized();
  return out;
}

}  // namespace rockface::ui
