#pragma once
// Region growing led by the distance to a fitted plane rather than by the
// normals of single triangles: the second pass of facet search (facets.h).
// On a face seen obliquely, dense matching's depth noise and terraces tilt
// every small triangle by more than the angle tolerance, even after
// smoothing, so growing on normals finds nothing there; the points
// themselves still lie within the stated depth precision of their plane.
// A seed is a patch of the triangle graph about the size of the smallest
// facet; its points' best-fit plane is kept when they lie within the
// precision of it, and the region then takes every neighbouring triangle
// whose three corners lie within the planarity gate of the (refitted)
// plane.
#include <vector>

#include "core/measure/facets/triangle_graph.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

struct PlaneLedOptions {
  double gate = 0;            // m: a corner farther off the plane keeps its triangle out
  double seed_rms = 0;        // m: a seed patch whose points scatter more is no plane
  double seed_area = 0;       // m^2: the seed patch's area (the smallest facet)
  double refit_growth = 1.5;  // the plane is refitted each time the region grows by this
};

// Regions (lists of triangle indices, disjoint) grown from `seeds`, tried
// in their order, over the usable triangles not `taken` (taken: in a facet
// already). A seed patch that fails marks its triangles as tried: each
// triangle is in at most one seed patch, so the cost stays linear in the
// mesh. The regions are not yet measured (facets.cpp does, like any other).
std::vector<std::vector<int>> plane_led_regions(const photogrammetry::SurfaceMesh& mesh,
                                                const TriangleGraph& graph,
                                                const std::vector<char>& taken,
                                                const std::vector<int>& seeds,
                                                const PlaneLedOptions& options);

}  // namespace rockface::measure
