#pragma once
// Convexity of a block and of its faces.
#include "core/blocks/polyhedron.h"

namespace rockface::blocks {

// Whether the polygon of face f is convex (no reflex corner, seen from outside).
bool face_is_convex(const Polyhedron& block, int f);
// Whether the block is convex: all faces convex and every vertex on the
// block's side of every face plane (all vertices on the convex hull). Both
// within kConvexityRel x size().
bool is_convex(const Polyhedron& block);

}  // namespace rockface::blocks
