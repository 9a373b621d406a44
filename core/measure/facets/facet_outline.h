#pragma once
// The outline of a facet: the boundary edges of its triangles chained into
// closed loops (the outer one and its holes), in the model frame, thinned
// by Douglas-Peucker to a given tolerance so that a facet of a 24 Mpx model
// is a polyline of tens of points, not thousands.
#include <vector>

#include <Eigen/Core>

#include "core/measure/facets/triangle_graph.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

struct FacetOutline {
  std::vector<Eigen::Vector3d> outer;  // closed: the last point joins the first (not repeated)
  int holes = 0;                       // further loops inside (gaps in the facet)
  double perimeter = 0;                // m, of the outer loop before thinning
};

// The outline of the facet made of `triangles` (indices into the mesh).
// The outer loop is the longest boundary loop. `tolerance` (m) is the
// largest distance of a dropped boundary point from the thinned outline; 0
// keeps every point. With the mesh's triangle graph and `position` (-1 for
// each of its triangles, left so) the boundary is read off the graph's
// neighbours instead of every edge's key: the same outline, faster.
FacetOutline facet_outline(const photogrammetry::SurfaceMesh& mesh,
                           const std::vector<int>& triangles, double tolerance,
                           const TriangleGraph* graph = nullptr,
                           std::vector<int>* position = nullptr);

// Douglas-Peucker on a closed polyline (at least the two farthest-apart
// points are kept).
std::vector<Eigen::Vector3d> thin_closed_polyline(const std::vector<Eigen::Vector3d>& loop,
                                                  double tolerance);

}  // namespace rockface::measure
