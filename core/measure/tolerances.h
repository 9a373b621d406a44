#pragma once
// Named tolerances and defaults of core/measure. Each says what error it
// absorbs or what it trades.

namespace rockface::measure {

// A plane fitted to a trace is reported only when its normal is known to
// this angle (one standard deviation, degrees); otherwise "orientation
// unknown". A compass reading is good to 1-2 degrees: a fit much worse than
// that would be a confident wrong dip.
inline constexpr double kMaxPlaneSigmaDeg = 5.0;

// Relief (RMS spread across the trace line, and off the local face) must
// exceed this many point sigmas to come from the rock and not from the
// noise of the 3D image: a straight trace on a flat face has ~1 sigma of
// both and defines no plane.
inline constexpr double kMinReliefInSigmas = 3.0;

// A trace whose points scatter off their best-fit plane by more than this
// many point sigmas (RMS) is not one plane (two joints, or a pick that
// jumped to another surface).
inline constexpr double kMaxPlanarityInSigmas = 4.0;

// Robust fit: points farther from the plane than this many sigmas (the
// larger of the point precision and the residuals' robust spread) are
// dropped and the plane refitted: picks across a step of the face, or onto
// something in front of it. When more than kMaxOutlierFraction of the
// points go, the trace is not one plane.
inline constexpr double kOutlierInSigmas = 3.0;
inline constexpr double kMaxOutlierFraction = 0.25;

// Densification of a picked polyline: one pick every this many pixels of
// the photograph, so that a trace of a few taps still gives the fit its
// hundreds of points.
inline constexpr double kTraceSampleStepPx = 2.0;

// A trace end within this many pixels of the image border or of a pixel
// with no surface under it is at the edge of the mapped area: its trace
// length is censored.
inline constexpr double kCensoringMarginPx = 6.0;

// Ray-triangle intersection: barycentric slack absorbing rounding, so a ray
// through a shared edge or vertex hits one of the triangles.
inline constexpr double kBarycentricSlack = 1e-9;

// Least-cost tracing: the search corridor around the straight line between
// the two taps, as a fraction of their distance (at least kMinCorridorPx).
inline constexpr double kCorridorFraction = 0.25;
inline constexpr double kMinCorridorPx = 24.0;

// Clustering: poles farther than this from every set mean (degrees) are
// left unassigned (scattered joints), and automatic clustering does not
// split sets whose means are closer than kMinSetSeparationDeg.
inline constexpr double kMaxSetMemberDeg = 35.0;
inline constexpr double kMinSetSeparationDeg = 20.0;

// Two located discontinuities of a set closer than this (m, along the set
// normal) are taken as one (the same joint mapped on two facets) when
// measuring spacing.
inline constexpr double kSameDiscontinuityM = 0.05;

// Facet sets (facets/facet_sets.h). A set of facets whose mean plane is
// within kFaceParallelDeg of the mapped surface's mean plane and whose facets
// cover at least kFaceShare of the mapped area is the excavation surface (a
// sprayed or blasted wall seen face-on), not a family of joints: the angle is
// what a face dressed by the excavation departs from its mean attitude.
inline constexpr double kFaceParallelDeg = 15.0;
inline constexpr double kFaceShare = 0.5;

// Compass readings of a trace (compass_reading.h, issue 27). A Clar compass
// laid on the exposed joint reads its dip and dip direction to 1-2 degrees
// (the paragraph of kMaxPlaneSigmaDeg): the reading's plane is given the
// larger of the two as its one-sigma uncertainty.
inline constexpr double kCompassSigmaDeg = 2.0;
// The trace must lie in the plane read: its line (and the plane fitted to
// it, where it has one) may leave that plane by the compass's own error
// (2 degrees), the direction of a short trace on the 3D image (a 1 m trace
// with 1 cm point precision: ~1 degree) and a joint's waviness over the
// metre the compass does not span (a few degrees; ISRM first-order
// roughness angles are typically 5-10 degrees); beyond this the reading or
// the trace is taken for the wrong joint and the measurement is marginal.
inline constexpr double kMaxTraceOffCompassDeg = 10.0;

// The rock side of a free face (free_face_side.h): the rock lies behind the
// face the camera saw. The photograph tells that side when every corner of
// the area (and its centroid) sees the face's plane from one side at more
// than this angle, or than kFreeFaceViewInSigmas sigmas of the plane's
// normal when that is larger: a plane fitted to a rough face stands for a
// surface whose local attitude departs from it by its roughness angle (ISRM
// first-order roughness 5-10 degrees, the paragraph of
// kMaxTraceOffCompassDeg), and a face seen within a few degrees of edge-on
// is where dense matching gives the fewest and poorest points (a point's
// error across the face grows as 1 / sin of the angle). Closer to edge-on
// the photograph does not tell the side; 3 sigmas: a sign wrong once in a
// thousand by the normal's own error.
inline constexpr double kMinFreeFaceViewDeg = 5.0;
inline constexpr double kFreeFaceViewInSigmas = 3.0;
// A pick's rock_side ("upper" | "lower": the half-space of the face's
// upward normal) swaps meaning as a face passes through vertical: a tunnel
// face leaning back 2 degrees has its rock "lower", overhanging 2 degrees
// "upper", and by eye the two are the same face (its lean is judged no
// better than its roughness angle, above). Within this angle of vertical a
// pick's rock_side that disagrees with the photograph is read as "behind
// the face" and the note says so; beyond it, a rock side the photograph
// contradicts is refused.
inline constexpr double kFreeFaceNearVerticalDeg = 5.0;

}  // namespace rockface::measure
