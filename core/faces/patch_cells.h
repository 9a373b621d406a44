#pragma once
// A surface patch, in its own 2D frame, cut into the cells of the trace
// lines of some joint planes: the convex polygons behind which the pieces
// of a non-convex block and the block around an island are built
// (trace_blocks.cpp, trace_block_pieces.cpp).
#include <vector>

#include <Eigen/Core>

#include "core/faces/free_surface.h"
#include "core/faces/trace_blocks.h"

namespace rockface::faces {

// The part of a convex polygon where n . x >= c (keep_upper) or <= c.
std::vector<Eigen::Vector2d> clip_convex(const std::vector<Eigen::Vector2d>& poly,
                                         const Eigen::Vector2d& n, double c, bool keep_upper);

// Signed area (counter-clockwise positive) and perimeter of a polygon.
double polygon_area(const std::vector<Eigen::Vector2d>& poly);
double polygon_perimeter(const std::vector<Eigen::Vector2d>& poly);

// The patch polygon cut by the trace lines of planes[which]: the cells of
// their arrangement on the patch (2D, patch frame). A plane parallel to
// the patch draws no line on it and cuts nothing.
std::vector<std::vector<Eigen::Vector2d>> cut_by_planes(const SurfacePatch& P,
                                                        const std::vector<TraceBlockPlane>& planes,
                                                        const std::vector<int>& which);

}  // namespace rockface::faces
