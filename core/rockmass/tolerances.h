#pragma once
// Named tolerances and thresholds of the rock-mass figures (DESIGN.md: no
// bare epsilons).

namespace rockface::rockmass {

// Deere's RQD counts core pieces of 100 mm or more.
inline constexpr double kRqdPieceM = 0.10;
// Two located discontinuities of one set closer than this along its normal
// are one joint seen twice (as core/measure's kSameDiscontinuityM).
inline constexpr double kSameDiscontinuityM = 0.05;
// Terzaghi's blind zone: a set whose normal makes more than this angle with
// the sampling line (or lies within 90 minus this of the face's plane, for a
// face) is sampled too thinly to correct; its weight is capped at
// 1 / cos(kBlindZoneDeg) (Terzaghi 1965; Priest 1993 caps at ~ 10).
inline constexpr double kBlindZoneDeg = 80.0;
// A straight trace (no plane of its own) belongs to the set whose trace
// direction on the face it follows within this angle.
inline constexpr double kTraceDirectionDeg = 15.0;
// A trace's plane belongs to the nearest set within this angle (as
// core/measure's kMaxSetMemberDeg).
inline constexpr double kSetMemberDeg = 35.0;
// Parallel scanlines per direction across the mapped face.
inline constexpr int kScanlinesPerDirection = 5;

// The support charts (q_support_chart.h, rmr_support_guidelines.h): a
// visit's point this close to a category boundary is reported on the
// documented side and as marginal, never flipped.
// Q: within 10 % of the boundary's Q at the visit's equivalent dimension
// (log10 1.1). Q is the product of six table readings, each a step of its
// table: one step of Ja (1 -> 2) or Jr (1.5 -> 2) already moves Q by a
// third or more, so a point within 10 % of a line is not decided by the data.
inline constexpr double kQChartMarginalLog10 = 0.0413926851582251;  // log10(1.1)
// A point this close (log10 Q) to a boundary is on it: the boundary's Q and
// the point's Q computed by different roundings (pow, log10) differ by a few
// units in the last place, and the line's side must not depend on them.
inline constexpr double kQChartOnLineLog10 = 1e-12;
// RMR89: within 2 points of a class boundary (the steps of tables A.3 and
// E between neighbouring columns are 2 to 5 points).
inline constexpr double kRmrClassMarginalPoints = 2.0;

}  // namespace rockface::rockmass
