#pragma once
// Named tolerances of core/mechanics. Each says what error it absorbs.

namespace rockface::mechanics {

// Barton's criterion is not used beyond a peak friction angle of 70 degrees
// (Barton & Choubey 1977): at very low normal stress log10(JCS / sigma_n)
// grows without bound, and the recommended cap keeps the peak physical.
inline constexpr double kMaxPeakFrictionDeg = 70.0;

// Return mapping of a slipping contact: the plastic slip increment is found
// by bracketing; it stops when the bracket is below this fraction of the
// elastic trial slip (the traction is then exact to the same fraction).
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

// An eigenvalue of M^-1 K is complex (flutter) when its imaginary part
// exceeds this fraction of the largest modulus: non-symmetric tangents from
// friction and follower loads carry rounding of that order otherwise.
inline constexpr double kComplexEigenRel = 1e-7;
// ... and real non-positive (divergence) below this fraction.
inline constexpr double kZeroEigenRel = 1e-9;

}  // namespace rockface::mechanics
