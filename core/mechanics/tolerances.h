#pragma once
// Named tolerances of core/mechanics. Each says what error it absorbs.

namespace rockface::mechanics {

// Barton's criterion is not used beyond a peak friction angle of 70 degrees
// (Barton & Choubey 1977): at very low normal stress log10(JCS / sigma_n)
// grows without bound, and the recommended cap keeps the peak physical.
inline constexpr double kMaxPeakFrictionDeg = 70.0;

// Return mapping of a slipping contact: the plastic slip increment (and the
// normal stress its dilation brings) is found by Newton kept inside a
// bracket; it stops when the equation's residual, or the bracket, is below
// this fraction of the elastic trial traction (trial slip), so the
// traction is exact to the same fraction.
inline constexpr double kReturnMappingRel = 1e-12;
inline constexpr int kReturnMappingIterations = 200;

// Newton corrector of one continuation step: converged when the residual,
// scaled by the block's load (forces) and load x size (moments), is below
// this. Loads are known to a few digits; 1e-9 is far below that and well
// above rounding (~1e-14 for sums of a few hundred contact forces).
inline constexpr double kEquilibriumResidual = 1e-9;
inline constexpr int kNewtonIterations = 30;

// Forward-difference step of the tangent, as a fraction of the elastic
// displacement of the block on its joints (load / total normal stiffness):
// small against the joints' elastic range, large against rounding.
inline constexpr double kTangentStepRel = 1e-4;

// Forward-difference step of dR/dp, relative to max(1, |p|): the residual
// depends smoothly on the load factor between slip events.
inline constexpr double kParameterStepRel = 1e-7;

// A pivot of the (scaled, order-one) Newton matrix below this is singular:
// scaled stiffnesses are O(1), rounding of the differences ~1e-12.
inline constexpr double kSingularPivotRel = 1e-10;

// A Newton step moving the scaled unknowns by more than this x (1 + |x|)
// has left the basin of the solution (the block runs away): the step fails.
inline constexpr double kMaxNewtonMove = 1e4;
inline constexpr int kLineSearchHalvings = 6;

// A continuation step is retried at half the length when its corrector
// lands farther than kCorrectorReach x the step from the prediction, or its
// tangent turns by more than acos(kSharpTurnCos) = 60 degrees: Newton may
// have jumped to another branch of the path (at the minimum step the point
// is kept: a perfectly plastic limit turns the path by 90 degrees).
inline constexpr double kCorrectorReach = 1.0;
inline constexpr double kSharpTurnCos = 0.5;
// ... and grows by 1.5 after an easy step (<= 3 Newton iterations) whose
// tangent turned by less than acos(kSmoothTurnCos) = 18 degrees.
inline constexpr double kSmoothTurnCos = 0.95;

// The displacement unit of path following is at least this fraction of
// the joints' slip scale (peak displacement): the differences of the
// tangent (kTangentStepRel of it) stay below the elastic displacement of a
// 1e12 Pa/m joint under a few metres of rock (1e-8 m) for peak
// displacements up to 1e-2 m.
inline constexpr double kSlipScaleFraction = 1e-2;

// A step of the path moves the block by at most this fraction of the
// joints' slip scale (peak displacement) in the scaled unknowns: a staged
// law integrates its history (slip, dilation at the step's end stress,
// dissipated energy) over each step, and with the exact tangent Newton
// would take steps across the whole peak. 2 % keeps the limit point within
// ~0.05 % of its converged value (1 % and 5 % move it by 0.03 % and 0.3 %
// on the wedge of the tests at 1e10 Pa/m; uncapped, by 1 %).
inline constexpr double kPathSlipFraction = 0.02;

// Loads are applied in kLoadIncrements increments at first, halved on
// failure down to 1 / kLoadIncrementsMax of the load.
inline constexpr int kLoadIncrements = 4;
inline constexpr int kLoadIncrementsMax = 1024;

// A failure mode turns (rather than translates) when some point of the
// block moves less than this fraction of its fastest point: a pivot, a
// hinge or a centre of rotation lies in or at the block.
inline constexpr double kPivotSpeedRel = 0.25;

// An eigenvalue of M^-1 K is complex (flutter) when its imaginary part
// exceeds this fraction of the largest modulus: non-symmetric tangents from
// friction and follower loads carry rounding of that order otherwise.
inline constexpr double kComplexEigenRel = 1e-7;
// ... and real non-positive (divergence) below this fraction.
inline constexpr double kZeroEigenRel = 1e-9;

}  // namespace rockface::mechanics
