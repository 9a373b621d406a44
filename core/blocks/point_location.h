#pragma once
// Where a point lies relative to a block: inside, on its surface or outside
// (by the winding number of the closed triangulated surface, exact for
// non-convex blocks).
#include <Eigen/Core>

#include "core/blocks/polyhedron.h"

namespace rockface::blocks {

enum class PointLocation { Inside, OnSurface, Outside };

// point: datum-relative. tolerance: metres within which a point counts as on
// the surface (negative: kOnSurfaceRel x size()).
PointLocation locate_point(const Polyhedron& block, const Eigen::Vector3d& point,
                           double tolerance = -1);

// Distance from a datum-relative point to the surface of the block.
double distance_to_surface(const Polyhedron& block, const Eigen::Vector3d& point);

}  // namespace rockface::blocks
