#pragma once
// The size the block's motion is measured by (its length unit L, and so
// its drift bound and contact tolerances): the block's diameter, the
// largest distance between two of its corners. Unlike the bounding box's
// diagonal (Polyhedron::size) it does not change when the same block is
// given turned (issue 40): the motion must not depend on the frame.
#include "core/blocks/polyhedron.h"

namespace rockface::mechanics {

// m; 0 for a block of fewer than two corners.
double block_diameter(const blocks::Polyhedron& block);

}  // namespace rockface::mechanics
