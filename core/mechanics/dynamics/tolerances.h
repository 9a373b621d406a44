#pragma once
// Named tolerances of the block's motion after failure. Lengths are in
// units of the block's size L (its diameter, block_diameter.h: the same in
// every frame), times in units of its free-fall time T = sqrt(L / |g|),
// forces in units of its weight W: one set of numbers serves a 1 mm chip
// and a 100 m slab.

namespace rockface::mechanics {

// A contact is closed while its gap is below this x L (and open beyond):
// far above the rounding of datum-relative coordinates (1e-16 x L) and the
// drift left after projection, far below anything a geologist measures.
inline constexpr double kContactGapRel = 1e-7;

// The bound kept on constraint drift: after every accepted step the
// contacts that carry load are projected back onto their joint planes to
// within this x L (and no closed contact penetrates deeper); unit
// quaternions are renormalised to 1e-15.
inline constexpr double kDriftBoundRel = 1e-9;

// Speeds below this x sqrt(|g| L) are rest: a contact slips only above it
// (below, static friction holds it if it can), and a closed contact
// separates only above it. It lies above the velocity error of the
// stepper's intermediate stages (rel_tol 1e-6 at the fast preset, of a
// velocity that is itself below sqrt(g L)), so that no stage flips a
// contact between stick and slip on noise.
inline constexpr double kRestSpeedRel = 1e-6;

// A contact point more than this x L inside the rock (or a rock corner
// that deep inside the block, or inside it behind another face) has not
// come through this joint surface within one step: it passed round the
// surface's edge, where the model has no rock, and is not a contact.
inline constexpr double kMaxPenetrationRel = 0.1;

// A contact carries load when its normal force exceeds this x W; a plane
// is in contact when the forces on it sum to more than this x W.
inline constexpr double kLoadedForceRel = 1e-7;

// Active points of one plane closer than this x L to one point are a
// corner, to one line an edge (rotation about it); otherwise a face.
inline constexpr double kPivotSpreadRel = 1e-4;

// An edge's line named after two loaded surfaces only when the loaded
// points' line runs within this angle of the surfaces' line of
// intersection: the points lie within kPivotSpreadRel x L of their line,
// so its direction is known to ~1e-4 L over the points' spread (a few
// tenths of L): 0.01 rad leaves a wide margin above that and far below
// the angles between a wedge's edges.
inline constexpr double kPivotAngleRad = 1e-2;

// A block whose loaded points lie on a line is said to turn about that
// line only while its angular velocity runs within this angle of it. A
// rotation about an edge has its angular velocity along the edge to the
// integration's error (~1e-7 rad); 5 degrees is where a geologist would no
// longer call the motion a turn about that edge (issue 39: 55 degrees off
// it was told as "rotates about edge").
inline constexpr double kAxisAngleRad = 5.0 * 3.14159265358979323846 / 180.0;

// Point-in-polygon tests of the joint surfaces include their boundary
// within this x L: a corner of the block on the edge of the rock's surface
// (every corner, at the start) is supported.
inline constexpr double kSupportEdgeRel = 1e-9;

// Active-set solution of the contact problem: complementarity is met when
// no force is below -kLcpRel x W and no contact accelerates into the rock
// faster than kLcpRel x |g| (far above rounding of 6x6 sums, far below the
// integration tolerances).
inline constexpr double kLcpRel = 1e-10;
inline constexpr int kLcpIterations = 200;
// Contacts at rest: at most this many rounds refine the way they slip
// (each round one solution of the contact problem) before it is taken.
inline constexpr int kStickSlipRounds = 12;

// Events (contact switches, impacts, landing) are located by bisection of
// the integration step down to this x T.
inline constexpr double kEventTimeRel = 1e-9;

// Free flight after the last contact is followed to the floor for at most
// this long (s) beyond the scene's duration: 60 s of fall is 17 km.
inline constexpr double kMaxFlightSeconds = 60.0;

// ---- bounds: the integration always ends (issue 41) ----
// At most this many steps of max_step_s over the duration are asked for
// (duration_s / max_step_s): the longest scene duration (600 s) at the
// precise preset's 5 ms is 120 000. Beyond it the input is refused.
inline constexpr double kMaxDynamicsStepsAsked = 200000;
// The step budget: at most this many evaluations of the equations of
// motion (about 20 us each). A wedge that slides and lands in 6 s takes
// 5 000 (standard) to 12 000 (precise); 120 000 steps of about 7
// evaluations each fit. A motion whose steps shrink to nothing (contacts
// that switch at every step) stops here instead of running for hours.
inline constexpr int kDynamicsEvaluationBudget = 2000000;
// At most this many events (contact switches, impacts): a sliding wedge
// has a handful; thousands within a few seconds are a chatter the model
// cannot follow, and the integration stops saying so.
inline constexpr int kMaxDynamicsEvents = 1000;
// The step floor: a step the error control shrinks below this x T is lost
// in the rounding of the time it is added to (T is about 1 in these units,
// the time up to ~1e3). The integration stops there and says so, as at the
// budget; it used to throw, which lost the report of every block.
inline constexpr double kStepFloorRel = 1e-14;
}  // namespace rockface::mechanics
