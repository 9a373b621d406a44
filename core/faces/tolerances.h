#pragma once
// Named tolerances of core/faces. Lengths that come from hand marking scale
// with the scene's snap tolerance (analysis.snap_tolerance, default 0.05 m);
// the others absorb rounding only.

namespace rockface::faces {

// Default snap tolerance (m) when a caller has none: a trace marked by hand
// on a reconstructed face is good to a few centimetres.
inline constexpr double kDefaultSnapTolerance = 0.05;

// sin of the angle below which two lines on a patch are parallel to working
// precision: their intersection point is not computed (the parameters would
// be ~1 / sin).
inline constexpr double kParallelSine = 1e-12;

// A joint plane within this angle (sine) of a patch plane has no trace line
// on it: the intersection direction would be undefined.
inline constexpr double kTraceOnPatchSine = 1e-6;

// A fitted trace plane is accepted only when the trace's relief (its spread
// across its own best-fit line, RMS) is large enough for the marking error
// (the snap tolerance) to tilt the plane by less than this angle.
inline constexpr double kMaxFitUncertaintyDeg = 10.0;

// A fitted or given plane whose points scatter off it by more than this many
// snap tolerances (RMS for a fit, maximum for a given joint) is not the
// trace's plane.
inline constexpr double kPlanarityInTolerances = 1.0;
inline constexpr double kGivenPlaneResidualInTolerances = 2.0;

// A parameter along a segment (m) counts as inside it with this slack: points
// computed by intersecting lines carry ~1e-15 relative error.
inline constexpr double kParamSlackRel = 1e-9;

// Corners of a patch polygon: a turn to the right sharper than this (sine)
// makes the patch non-convex. Collinear corners (T-junctions where a long
// patch edge meets two shorter ones) are allowed.
inline constexpr double kConvexCornerSine = 1e-9;

// A convex cell of a non-convex loop thinner than this fraction of the snap
// tolerance (twice area over perimeter) lies in the band where snapped
// stretches and exact trace lines differ: its side of a plane is not
// decided by the map, and it adds no piece to the block.
inline constexpr double kThinCellInTolerances = 0.5;

// Two joints of a loop within the orientation uncertainty of parallel, its
// block between them, that would meet only further than this many times
// the loop's size from it are parallel for the block's verdicts: nothing
// measured tells them from parallel, and a trace block assumes its joints
// persist across the block, not to where two of one set would meet (issue
// 43: 0.0002 degrees and 0.6 m apart, they met 1,000 km out). Two that meet
// closer bound a wedge that closes where they meet (a sliver between
// traces that cross at a corner of the loop): it is built as it is.
inline constexpr double kParallelMeetInLoopSizes = 10;

}  // namespace rockface::faces
