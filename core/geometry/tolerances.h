#pragma once
// Named tolerances of core/geometry. No bare epsilons elsewhere in geometry:
// each value says what error it absorbs.

namespace rockface::geometry {

// Unit vectors built from double-precision trigonometry carry ~1e-16 error per
// component; dot products of them ~1e-15. A margin (angle) below this cannot
// be told from zero by arithmetic and is reported as marginal regardless of
// the measurement uncertainty.
inline constexpr double kAngleEpsRad = 1e-12;

// Two directions closer than this are the same ray when collecting the edges
// of a cone (dedupe of numerically repeated candidates).
inline constexpr double kSameRayRad = 1e-9;

// A cross product shorter than this comes from planes parallel to working
// precision; it defines no line and is skipped, not normalised.
inline constexpr double kParallelCross = 1e-14;

// Two half-space normals whose sum is shorter than this are treated as
// opposite when searching a cone's margin: their bisector candidate is then
// badly conditioned, so the points of the whole bisecting circle are added.
// Adding candidates never lowers the margin, so the value only needs to be
// generous, not exact.
inline constexpr double kOppositeNormals = 1e-3;

// Two planes within this angle of parallel are parallel to rounding: the
// same dip and dip direction through different arithmetic (a normal turned
// back from a fitted face, the trigonometry of a datum's shift) differ by
// ~1e-15. Beyond it only the orientation uncertainty of the measurements
// makes two planes parallel (core/geometry/parallel_planes.h).
inline constexpr double kParallelRoundingRad = 1e-9;

// Default orientation uncertainty of a hand measurement (compass-clinometer
// readings are good to 1-2 degrees). A verdict whose margin is inside it is
// reported as marginal; a scene may set its own value.
inline constexpr double kDefaultOrientationUncertaintyDeg = 1.0;

}  // namespace rockface::geometry
