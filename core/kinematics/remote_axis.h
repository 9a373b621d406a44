#pragma once
// Remote-axis rotation: is there any axis in space (a point and a unit
// direction, not necessarily through the block) about which the block can
// start to rotate without any corner entering the rock behind a joint?
//
// For the axis through p with unit direction u, a corner C moves along
// d = u x (C - p). For each joint through C with block-side normal n, the
// angle delta by which d dips below the joint plane (sin delta = -d.n/|d|,
// zero when d points to the block side or along the plane) is penalised by
// 1 - cos(delta) (the 1 - cos(alpha - pi/2), alpha the angle between
// d and n); the objective is the sum. It is zero exactly on the feasible
// axes, smooth (quadratic) where a constraint starts to be violated, and
// bounded (at most 1 per constraint), so one badly placed corner cannot
// swamp the others.
//
// Why the trivial solutions are not a problem here:
//   - Zero motion: u is a unit vector by construction (the minimiser works
//     in a chart of the unit sphere), so no parameter can scale the motion
//     away; the penalty uses the direction of d only, so the axis distance
//     does not scale it either.
//   - Corners on the axis: a corner within kOnAxisRel of the axis does not
//     move and gives zero penalty - truly, not as a loophole: the rest of
//     its faces is covered by their other corners, because the displacement
//     is linear along a face. Approaching the corner from the infeasible
//     side keeps the penalty up (d turns with the approach, it does not
//     shrink in the objective), so the minimiser cannot slide onto it.
//   - Translations: an axis far away moves every corner almost in parallel;
//     a removable block is (correctly) found movable that way, and the
//     reported axis is then far from the block (distance in the result).
// Slumping (rotation while in sliding contact with two joints) has its
// displacements exactly along those joints: they are admitted (delta = 0
// there), so such axes are found as the limit of the minimisation.
//
// The search is a multi-start: `starts` axes drawn from std::mt19937(seed)
// (directions uniform on the sphere, points uniform in a disc of
// kRemoteAxisStartRadius bounding radii across the axis through the
// centroid), each minimised by Eigen's Levenberg-Marquardt on the residuals
// r = 2 sin(delta / 2) (so that the objective is r.r / 2). A start hits when
// it ends with every violation below kRemoteAxisHitRad.

#include <Eigen/Core>

#include "core/common/preset.h"
#include "core/kinematics/rotation_input.h"

namespace rockface::kinematics {

struct RemoteAxisOptions {
  int starts = 64;
  unsigned seed = 1;
  // Stop once an axis is found and the hit rate has settled (the rule and
  // its error: rotation_tolerances.h, kRemoteAxisHitRateError). The starts
  // run are the first ones of the full search (same seed, same order), so
  // found / not found is the full search's, and hits / starts estimates
  // the same hit rate.
  bool early_stop = false;
};

// Starts of the named preset (docs/accuracy-cost.md, remote-axis table):
// fast 16, standard 64, precise 256. The search costs ~0.35 ms per start;
// more starts buy confidence in a "no axis" answer.
int remote_axis_starts(Preset preset);

struct RemoteAxisResult {
  bool found = false;  // some start reached a feasible axis
  // The best axis: among hits the one with the largest clearance, else the
  // one with the least penalty. point: the axis point nearest the block's
  // centroid (datum-relative, like the input).
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  double distance = 0;       // m, from the centroid to the axis
  int starts = 0, hits = 0;  // starts run (fewer than asked when stopped early)
  bool stopped_early = false;
  double penalty = 0;        // objective at the best axis
  double max_violation = 0;  // radians, largest delta at the best axis
  // radians: min over the constraints of the angle by which d points to
  // the block side (> 0: every corner lifts off; 0: sliding contact).
  double clearance = 0;
  int constraints = 0;  // (corner, joint) pairs checked
};

// The objective for one axis (point datum-relative, direction any length).
double remote_axis_penalty(const RotationInput& in, const Eigen::Vector3d& point,
                           const Eigen::Vector3d& direction);

// Largest violation angle (radians) and clearance of one axis, as above.
struct AxisFeasibility {
  double penalty = 0, max_violation = 0, clearance = 0;
};
AxisFeasibility remote_axis_feasibility(const RotationInput& in, const Eigen::Vector3d& point,
                                        const Eigen::Vector3d& direction);

// Multi-start search. Throws InputError for starts < 1 or a malformed block.
RemoteAxisResult search_remote_axis(const RotationInput& in, const RemoteAxisOptions& options);

}  // namespace rockface::kinematics
