#pragma once
// The triangles of a 3D image as a graph for region growing: each
// triangle's area, centre and normal, and its neighbours across shared
// edges. Degenerate triangles (zero area, an index out of range, a vertex
// not finite) have no normal and no neighbours: they join no facet.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

struct TriangleGraph {
  std::vector<Eigen::Vector3d> normals;  // unit, or zero for a degenerate triangle
  std::vector<Eigen::Vector3d> centres;
  std::vector<double> areas;  // m^2
  // Up to three neighbours across the edges (opposite vertex 0, 1, 2), or
  // no neighbour (negative): kBorder, an edge of no other usable triangle;
  // kSharedByMore, an edge shared by more than two.
  static constexpr int kBorder = -1, kSharedByMore = -2;
  std::vector<std::array<int, 3>> neighbours;

  std::size_t size() const { return normals.size(); }
  bool usable(std::size_t t) const { return normals[t].squaredNorm() > 0; }
};

// Throws InputError("mesh", ...) when the mesh has more than 2^31 triangles.
TriangleGraph triangle_graph(const photogrammetry::SurfaceMesh& mesh);

// The normals averaged (area-weighted) with their neighbours `passes` times
// (each pass: the triangle and the triangles sharing an edge with it), a
// diffusion over about sqrt(passes) triangles.
// Normals are oriented consistently with the triangle's own before summing.
std::vector<Eigen::Vector3d> smoothed_normals(const TriangleGraph& graph, int passes);

// How bent the surface is at each triangle: the largest angle (radians)
// between its normal and those of its neighbours (a crease, an edge of the
// face or noise). Seeds of region growing are taken flattest first.
std::vector<float> bending(const TriangleGraph& graph, const std::vector<Eigen::Vector3d>& normals);

}  // namespace rockface::measure
