#include "ui/view3d/display_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

// Triangles of `indices` over `positions` (xyz floats) clustered on a grid
// grown from `cell` until at most `budget` remain; every kept corner is one
// of the given vertices, so the vertex buffers are shared.
std::vector<std::uint32_t> clustered_indices(const std::vector<float>& positions,
                                             const std::vector<std::uint32_t>& indices, double cell,
                                             std::size_t budget) {
  const std::size_t n = positions.size() / 3;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  for (std::size_t i = 0; i < n; ++i)
    low =
        low.cwiseMin(Eigen::Vector3d(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]));
  std::vector<std::uint32_t> out;
  std::vector<std::uint32_t> representative(n);
  for (;;) {
    std::unordered_map<std::int64_t, std::uint32_t> first;
    constexpr std::int64_t kCells = 1 << 20;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
      const Eigen::Vector3d c = ((p - low) / cell).array().floor();
      const std::int64_t key =
          (static_cast<std::int64_t>(c.x()) * kCells + static_cast<std::int64_t>(c.y())) * kCells +
          static_cast<std::int64_t>(c.z());
      representative[i] = first.try_emplace(key, static_cast<std::uint32_t>(i)).first->second;
    }
    out.clear();
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
      const std::uint32_t a = representative[indices[t]], b = representative[indices[t + 1]],
                          c = representative[indices[t + 2]];
      if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
    }
    if (out.size() / 3 <= budget) return out;
    cell *= std::sqrt(2.0);
  }
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
  const std::size_t turning_budget = max_triangles / kTurningBudgetDivisor;
  if (turning_budget > 0 && out.triangle_count() > turning_budget) {
    // An eighth of the triangles: a cell about sqrt(8) times the display's.
    const double start =
        out.cell > 0 ? out.cell * std::sqrt(8.0)
                     : 2 * out.radius /
                           std::sqrt(static_cast<double>(std::max<std::size_t>(turning_budget, 1)));
    out.turning_indices = clustered_indices(out.positions, out.indices, start, turning_budget);
  }
  return out;
}

}  // namespace rockface::ui
