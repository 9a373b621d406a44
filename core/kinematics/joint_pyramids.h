#pragma once
// Block theory on joint pyramids (Goodman & Shi): every joint-pyramid code
// against an excavation pyramid, with emptiness, finiteness and removability
// decided by cone margins, and the translational mode of each removable one.
//
// The joint pyramid JP of a code is the intersection of the half-spaces the
// code names (0 = upper = the side the upward normal points to, 1 = lower).
// The excavation pyramid EP is the intersection of the free faces' rock-side
// half-spaces (several faces forming a convex corner or edge of an
// excavation are one EP). Shi's theorem: the block is finite iff JP cap EP is
// empty, and removable iff it is finite and JP is not empty.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/cone.h"
#include "core/geometry/plane.h"
#include "core/geometry/verdict.h"
#include "core/kinematics/sliding_mode.h"

namespace rockface::kinematics {

struct JointSpec {
  Eigen::Vector3d normal;          // unit upward normal
  std::optional<double> friction;  // radians
};

struct FreeFaceSpec {
  Eigen::Vector3d normal;  // unit upward normal
  geometry::HalfSpace rock_side = geometry::HalfSpace::Lower;
};

// The excavation pyramid of one free face or of a convex group of them.
geometry::Cone excavation_pyramid(const std::vector<FreeFaceSpec>& faces);

// The joint pyramid of a code (one HalfSpace per joint; NotInvolved skips it).
geometry::Cone joint_pyramid(const std::vector<JointSpec>& joints,
                             const std::vector<geometry::HalfSpace>& code);

struct PyramidVerdict {
  std::vector<geometry::HalfSpace> code;
  std::string code_text;            // "101": one digit per joint
  double jp_margin = 0;             // radians, signed: > 0 JP has an interior
  double jp_ep_margin = 0;          // radians, signed: > 0 JP cap EP has an interior
  bool empty = false;               // JP has no interior
  bool finite = false;              // JP cap EP has no interior
  geometry::Verdict removable;      // with its margin and marginal flag
  std::optional<SlidingMode> mode;  // removable pyramids only
};

struct PyramidOptions {
  double uncertainty = 0;  // radians: orientation uncertainty of the joints
  // Active resultant for the mode analysis (any scale: gravity plus seismic
  // per unit mass, or a force); zero skips the mode analysis.
  Eigen::Vector3d resultant = Eigen::Vector3d::Zero();
};

// Every code of the n joints (2^n of them) against one EP. Throws
// InputError("joints") for n > 20: the table would not fit in memory.
std::vector<PyramidVerdict> analyse_joint_pyramids(const std::vector<JointSpec>& joints,
                                                   const geometry::Cone& excavation,
                                                   const PyramidOptions& options);

// One code against one EP (the step above, exposed for blocks and tests).
PyramidVerdict analyse_joint_pyramid(const std::vector<JointSpec>& joints,
                                     const std::vector<geometry::HalfSpace>& code,
                                     const geometry::Cone& excavation,
                                     const PyramidOptions& options);

}  // namespace rockface::kinematics
