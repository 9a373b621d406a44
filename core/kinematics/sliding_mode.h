#pragma once
// Translational failure mode of a removable block or joint pyramid under a
// resultant force, after Goodman & Shi's rules, and its limit-equilibrium
// factor of safety.
//
// The block touches its joint planes; each contact is given by the unit
// normal pointing from the plane into the block (the block-side normal, so
// that the block can move along s only if s . normal >= 0 for every contact).
// Under the resultant r the block
//   - falls (or lifts) when r itself points into the joint pyramid;
//   - slides on plane i when r presses on i (r . n_i < 0) and the projection
//     of r onto plane i points into the pyramid;
//   - slides on planes i and j when the direction of their intersection, taken
//     in the sense of r, points into the pyramid and r presses on both
//     (positive normal reactions from the decomposition r = t s - N_i n_i - N_j n_j);
//   - does not move otherwise (r pushes it into the rock).
// For a removable pyramid and a generic r exactly one mode applies. Where r
// lies on a boundary between modes the choice is made in the order above and
// flagged marginal; the factor of safety is continuous across those
// boundaries, so the number does not jump even where the label could.
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace rockface::kinematics {

struct ContactPlane {
  int plane = -1;                  // caller's plane index (scene order)
  Eigen::Vector3d block_normal;    // unit, from the plane into the block
  std::optional<double> friction;  // radians; none: no strength given
  double cohesion_force = 0;       // cohesion x contact area, N (0 for a pyramid)
};

enum class ModeType { Falling, Lifting, Sliding, None };
const char* mode_name(ModeType t);

struct SlidingMode {
  ModeType type = ModeType::None;
  std::vector<int> planes;                              // the sliding planes (caller's indices)
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit sliding direction, zero for None
  std::vector<double> normal_forces;  // N on each sliding plane (same order), >= 0
  double driving_force = 0;           // component of r along the direction, N
  // Resisting / driving; 0 for falling and lifting; infinity for None; none
  // when a sliding plane has no friction angle.
  std::optional<double> fos;
  double margin = 0;  // radians: how far r is from a mode boundary
  bool marginal = false;
};

// r: the active resultant (N); contacts: the joint planes bounding the block.
// uncertainty: radians of orientation uncertainty (a mode boundary closer
// than this makes the result marginal).
SlidingMode sliding_mode(const Eigen::Vector3d& resultant,
                         const std::vector<ContactPlane>& contacts, double uncertainty);

}  // namespace rockface::kinematics
