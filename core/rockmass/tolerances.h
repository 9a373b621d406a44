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

}  // namespace rockface::rockmass
