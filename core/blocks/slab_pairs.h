#pragma once
// The planes of a convex block that bound it on both sides as a slab: two
// half-spaces whose planes are within an angle of parallel, the block
// between them, that meet (if at all) only far from where the block is
// known. Such a pair is parallel for the block's verdicts: the angle
// between them is beyond what was measured, and where they would meet is
// beyond any joint's persistence (core/faces/trace_blocks.cpp). A pair that
// meets near the block bounds a wedge that closes there (a sliver) and is
// none of these.
#include <vector>

#include <Eigen/Core>

#include "core/blocks/construction.h"

namespace rockface::blocks {

struct SlabPair {
  int first = -1, second = -1;  // indices into the half-spaces, first < second
  double angle = 0;             // radians between the two planes
  double meet_distance = 0;     // m from `centre` to where they meet; infinity when parallel
};

// Pairs of the half-spaces within `tolerance` (radians) of parallel, the
// block on both sides, whose planes meet further than `reach` (m) from
// `centre` (datum-relative, as the planes).
std::vector<SlabPair> slab_pairs(const std::vector<HalfSpaceInput>& halfspaces, double tolerance,
                                 const Eigen::Vector3d& centre, double reach);

}  // namespace rockface::blocks
