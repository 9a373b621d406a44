#pragma once
// Named tolerances of core/blocks. Lengths are relative to the block's size
// (bounding-box diagonal) so the same block gives the same topology from 1 mm
// to 100 m.

namespace rockface::blocks {

// Vertices of a convex construction closer than this (x size) are one corner:
// four or more planes through one point give several numerically distinct
// triple intersections that differ by rounding (~1e-15 relative, amplified
// by the conditioning of the 3x3 solve).
inline constexpr double kVertexMergeRel = 1e-9;

// A survey's precision snaps planes through a shared corner by at most this
// (x size): the snap joins corners a block's planes miss each other by, it
// does not reshape a block whose size is near the survey's precision (such a
// block keeps its planes as given).
inline constexpr double kSurveySnapRel = 1e-3;

// A vertex lies on a plane when its distance is below this (x size); slightly
// larger than the merge distance so that a merged corner stays on every
// plane that produced it.
inline constexpr double kOnPlaneRel = 4e-9;

// Default planarity tolerance of a face given by vertices (x size): vertices
// computed by intersecting planes and written with 12+ significant digits
// meet it by far; a face visibly warped (1 mm on a 1 km block) does not.
inline constexpr double kFacePlanarityRel = 1e-6;

// A corner of a face or an edge of a block is reflex / the block convex
// within this (x size): a vertex this far outside a face plane breaks
// convexity.
inline constexpr double kConvexityRel = 1e-9;

// A face polygon with an area below this (x size^2) does not exist (a plane
// touching the block only along an edge).
inline constexpr double kFaceAreaRel = 1e-14;

}  // namespace rockface::blocks

namespace rockface::blocks {

// A point (a bolt head, the point of an applied force) closer than this (x
// size) to the block's surface is on it: such points are typically measured
// on the rock face to centimetres, so the default is generous.
inline constexpr double kOnSurfaceRel = 1e-3;

}  // namespace rockface::blocks

namespace rockface::blocks {

// Two faces meeting at an edge with outward normals closer than this (sine
// of the angle) are flat there: the edge is neither convex nor reflex.
inline constexpr double kReflexSine = 1e-12;

}  // namespace rockface::blocks
