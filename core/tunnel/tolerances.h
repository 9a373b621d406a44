#pragma once
// Named tolerances of core/tunnel. Each says what error it absorbs.

#include <cstddef>

namespace rockface::tunnel {

// Two stations closer than this (horizontally, m) are one point: an element
// between them has no length and no direction. Survey tables are given to
// the millimetre; 1e-6 m is far below that and far above the ~1e-10 m
// rounding of datum-relative doubles at 10^6 m.
inline constexpr double kSamePointM = 1e-6;

// The chainage difference of an element (a line or an arc between two
// stations of a surveyor's table) and the horizontal length of that element
// agree within this many metres plus kChainageMismatchRelative times the
// length: tables are rounded to the millimetre or centimetre and some give
// slope rather than horizontal lengths (1 per mille at a 4.5 % grade).
// Beyond it the table has a typo (a wrong chainage, a wrong radius).
inline constexpr double kChainageMismatchM = 0.01;
inline constexpr double kChainageMismatchRelative = 1e-3;

// A dense polyline's chainages are authoritative (the chord of a curve is
// shorter than its arc); only a gross mismatch between a segment's chord
// and its chainage difference (a typo) is refused.
inline constexpr double kPolylineMismatchRelative = 0.05;

// Profile segments whose ends are closer than this (m) join: design profiles
// are drawn to the millimetre.
inline constexpr double kProfileJoinM = 1e-4;

// A profile segment shorter than this (m) has no length. A micrometre:
// far below the millimetre of design drawings and of any excavation's
// survey, so that the short pieces a CAD drawing leaves (a 0.1 mm chamfer
// or join) are kept, and far above the ~1e-15 relative rounding of
// coordinates of metres (issue 40: 0.1 mm segments were refused). An arc
// whose ends lie within kProfileJoinM is a full circle, so an arc needs a
// chord above that.
inline constexpr double kProfileSegmentMinM = 1e-6;

// Arcs are drawn as chords whose sagitta stays below this (m) when the
// profile is checked for self-intersection and star shape.
inline constexpr double kProfileSagittaM = 1e-4;

// An outline that is not star-shaped is searched for the place where it
// crosses itself (pairwise, quadratic) only up to this many chords (2.5e7
// pairs, well under a second); a longer one is refused as not star-shaped.
inline constexpr std::size_t kProfileCrossingCheckChords = 5000;

// place() searches the alignment's elements through bounding spheres of
// this many consecutive elements at the leaves; a sphere is passed over
// when its nearest point lies farther than the best foot so far by more
// than this relative slack (rounding of the distances, ~1e-15 relative:
// no element that could be nearest or tie is ever passed over).
inline constexpr std::size_t kAlignmentBoundLeaf = 8;
inline constexpr double kAlignmentBoundSlackRel = 1e-9;

// Newton iterations of the foot point on a graded arc stop when the chainage
// step is below this (m): far below survey accuracy.
inline constexpr double kFootChainageM = 1e-9;

// A ray parallel to a triangle's plane to this (|cos| of the angle between
// the ray and the plane's normal) does not hit it.
inline constexpr double kRayParallel = 1e-12;

// A ray through a shared edge or vertex of two triangles must hit one of
// them: barycentric coordinates are accepted this far outside [0, 1]
// (rounding of u, v is ~1e-16 relative; a hit this far outside a triangle
// lies within 1e-9 of its size from it, far below any mesh's accuracy).
inline constexpr double kBarycentricSlack = 1e-9;

// ---- wedges around the excavation (wedge_*.h) ----
// A profile vertex where the outline turns by more than this (radians, 1
// degree) is a corner (a horseshoe's wall meeting its invert, a rectangle's
// corner); arcs drawn as chords turn by less at each chord (their sagitta
// is kept below a millimetre, see WedgeOptions), and the joins of tangent
// segments turn by rounding only.
inline constexpr double kWedgeCornerRad = 0.017453292519943295;
// Two wedge vertices closer than this, relative to the wedge's size, are one
// (the pieces of a wedge compute shared corners separately; they agree to
// ~1e-13 relative rounding).
inline constexpr double kWedgeVertexMergeRel = 1e-9;
// A corner of a perimeter wedge's piece this close to the wedge's apex,
// relative to the wedge's size, is the apex. Each piece finds the apex
// again as the meeting point of its joints; with two sets nearly parallel
// (0.001-0.04 deg) they meet at a grazing angle and the pieces' apexes
// scattered by ~1e-9 of the size, past kWedgeVertexMergeRel (the rounding
// is amplified by one over the angle: 1e-16 / 2e-5 rad ~ 5e-12 per
// operation, and the clipping takes several). 1e-6 keeps a margin of 50 at
// the smallest angle, and lies far below the apex's distance from the
// excavation (a wedge whose apex is within the chords' sagitta is left out
// as a sliver).
inline constexpr double kWedgeApexSnapRel = 1e-6;
// A joint pyramid edge whose projection on the cross-section is shorter than
// this (sine of its angle to the axis) runs along the axis: the wedges it
// bounds never end along the tunnel (a margin of 0).
inline constexpr double kWedgeAlongAxisSine = 1e-12;
// A joint set whose plane lies within this angle (radians) of containing
// the tunnel's axis is taken to contain it: 1e-6 rad (0.2 arc seconds),
// far below the degree to which a compass reads a dip, and a wedge's size
// moves by ~1e-6 of itself. Its wedges are then those of the exact limit:
// tilted by 1e-9 deg, the set's plane and the planes the wedge search lays
// along the axis were 1e-11 rad apart and the construction lost the roof
// and wall wedges, and a face wedge came and went with the tilt's sign
// (issue 40).
inline constexpr double kWedgeAxisParallelRad = 1e-6;
// A joint pyramid seen along the axis that is narrower than a half-plane
// by no more than this (radians) spans a half-plane: only a set containing
// the axis (taken so within kWedgeAxisParallelRad) makes a sector that
// wide, and its edges' projections are opposite but for rounding (~1e-16).
// Taken as pointed, its largest apex lay ~1e16 m out and its pieces were
// "not a bounded solid" (issue 40).
inline constexpr double kWedgeHalfPlaneRad = 1e-12;
// The face wedge's largest triangle is found by bisection of its scale to
// this relative precision (far below the sagitta of the profile's chords).
inline constexpr double kWedgeScaleRel = 1e-10;
// A trace-length limit is met by bisection on the apex's position to this
// relative precision of the limit.
inline constexpr double kWedgeTraceRel = 1e-6;
// Two joint sets whose poles are closer than this (radians), or than the
// orientation uncertainty when that is larger, are one set: a set listed
// twice differs by the rounding of degrees to a normal (~1e-15).
inline constexpr double kWedgeSameSetRad = 1e-9;
// Two sets of a wedge whose poles are closer than this (radians, 1 degree)
// are named near-parallel when its solid cannot be made: their planes meet
// at a grazing angle, the apex runs far out (14 m to 1.8e7 m on the issue's
// draws, sets 0.001 degree apart) and that is why (issue 40).
inline constexpr double kWedgeNearParallelRad = 0.017453292519943295;
}  // namespace rockface::tunnel
