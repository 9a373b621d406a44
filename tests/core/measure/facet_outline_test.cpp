// A facet's outline read off the triangle graph (facet_outline with the
// graph) against the same outline from every edge's key (without it, the
// way outlines were read before the graph was used: the reference, tested
// through the facets' own tests): the same outer points in the same order,
// holes and perimeter, on lattice patches of a bumpy surface with holes,
// two parts touching at a pinch vertex, a patch wound the other way, a
// triangle listed twice and an edge shared by three triangles (where the
// graph cannot tell and the keys decide).
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "core/measure/facets/facet_outline.h"
#include "core/measure/facets/triangle_graph.h"

namespace {

namespace rm = rockface::measure;

// An n x n lattice of vertices on a bumpy surface, two triangles a cell.
rockface::photogrammetry::SurfaceMesh lattice(int n) {
  rockface::photogrammetry::SurfaceMesh m;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      m.vertices.emplace_back(0.01 * x, 0.01 * y, 0.002 * std::sin(0.7 * x) * std::cos(0.5 * y));
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

void expect_same_outline(const rockface::photogrammetry::SurfaceMesh& mesh,
                         const std::vector<int>& tris, const char* what) {
  const rm::TriangleGraph graph = rm::triangle_graph(mesh);
  std::vector<int> position(graph.size(), -1);
  for (const double tolerance : {0.0, 0.015}) {
    const rm::FacetOutline by_keys = rm::facet_outline(mesh, tris, tolerance);
    const rm::FacetOutline by_graph = rm::facet_outline(mesh, tris, tolerance, &graph, &position);
    ASSERT_FALSE(by_keys.outer.empty()) << what;
    EXPECT_EQ(by_graph.outer, by_keys.outer) << what << ", tolerance " << tolerance;
    EXPECT_EQ(by_graph.holes, by_keys.holes) << what;
    EXPECT_EQ(by_graph.perimeter, by_keys.perimeter) << what;
  }
  for (const int p : position) ASSERT_EQ(p, -1) << what << ": the scratch was not left as given";
}

TEST(FacetOutlineByGraph, SameOutlinesAsFromEveryEdgesKey) {
  const auto mesh = lattice(60);
  cv::RNG rng(7);
  // Random blobs of triangles with random holes, in a shuffled order (the
  // order decides where a loop starts).
  for (int trial = 0; trial < 20; ++trial) {
    const int cx = rng.uniform(10, 49), cy = rng.uniform(10, 49), r = rng.uniform(4, 20);
    std::vector<int> tris;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
      const int cell = t / 2, x = cell % 59, y = cell / 59;
      const int dx = x - cx, dy = y - cy;
      const bool in = dx * dx + dy * dy <= r * r;
      const bool hole = (x + 3 * y) % 17 == 0 || rng.uniform(0, 30) == 0;
      if (in && !hole) tris.push_back(t);
    }
    cv::randShuffle(tris, 1.0, &rng);
    expect_same_outline(mesh, tris, "blob");
  }
}

TEST(FacetOutlineByGraph, PinchesWindingDuplicatesAndNonManifoldEdgesAsByKeys) {
  {
    // Two squares of cells touching at one vertex.
    const auto mesh = lattice(12);
    std::vector<int> tris;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
      const int cell = t / 2, x = cell % 11, y = cell / 11;
      if ((x < 4 && y < 4) || (x >= 4 && x < 8 && y >= 4 && y < 8)) tris.push_back(t);
    }
    expect_same_outline(mesh, tris, "pinch");
  }
  {
    // A band of cells wound the other way.
    auto mesh = lattice(12);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if ((t / 2) % 11 >= 5 && (t / 2) % 11 < 7)
        std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
    std::vector<int> tris;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) tris.push_back(t);
    expect_same_outline(mesh, tris, "winding");
  }
  {
    // One triangle listed twice.
    const auto mesh = lattice(10);
    std::vector<int> tris;
    for (int t = 0; t < 60; ++t) tris.push_back(t);
    tris.push_back(17);
    expect_same_outline(mesh, tris, "listed twice");
  }
  {
    // A third triangle on an inner edge (a fin): that edge is shared by
    // three.
    auto mesh = lattice(10);
    mesh.vertices.emplace_back(0.045, 0.045, 0.05);
    const auto t = mesh.triangles[40];
    mesh.triangles.push_back({t[0], t[2], static_cast<int>(mesh.vertices.size()) - 1});
    std::vector<int> tris;
    for (int i = 0; i < static_cast<int>(mesh.triangles.size()); ++i) tris.push_back(i);
    expect_same_outline(mesh, tris, "fin");
    const rm::TriangleGraph graph = rm::triangle_graph(mesh);
    EXPECT_EQ(graph.neighbours[40][1], rm::TriangleGraph::kSharedByMore);
  }
}

}  // namespace
