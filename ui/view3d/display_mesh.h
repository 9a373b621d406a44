#pragma once
// The model as the GPU draws it: float positions relative to the mesh
// centre, texture coordinates, colours and triangle indices, cut down to a
// triangle budget by vertex clustering (a 24 Mpx model has millions of
// triangles; the tablet's GPU, and the software renderer of the tests, show
// a fraction of them as well at screen resolution).
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "storage/project/project_records.h"

namespace rockface::ui {

struct DisplayMesh {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // project frame
  double radius = 0;                                 // of the bounding sphere around centre
  // Edge of the clustering grid cell (m); 0 when the mesh was not decimated.
  // A displayed vertex is within a cell's diagonal of the stored one.
  double cell = 0;
  Eigen::Vector3d mean_normal = Eigen::Vector3d::UnitZ();  // area-weighted, unit
  std::vector<float> positions;                            // xyz relative to centre
  std::vector<float> texcoords;                            // uv (empty: none)
  std::vector<std::uint8_t> colours;                       // rgb (empty: none)
  std::vector<std::uint32_t> indices;                      // three per triangle
  // The same vertices clustered again for an eighth of the budget: drawn
  // while a finger turns the view, when a software renderer cannot draw the
  // whole budget at the frame rate and nobody reads detail. Empty when the
  // mesh is already that small (the whole is drawn).
  std::vector<std::uint32_t> turning_indices;

  std::size_t triangle_count() const { return indices.size() / 3; }
};

// Share of the display budget drawn while the view turns.
constexpr std::size_t kTurningBudgetDivisor = 8;

// max_triangles = 0: keep them all (and no turning copy).
DisplayMesh make_display_mesh(const storage::Mesh& mesh, std::size_t max_triangles);

}  // namespace rockface::ui
