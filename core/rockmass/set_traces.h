#pragma once
// Which joint set each trace of the face belongs to. A trace is given to a
// set, in this order, by:
//   1. its joint's set as stored (the geologist's or the measure step's),
//   2. its own plane (a trace over relief), nearest set within kSetMemberDeg,
//   3. its direction on the face (a straight trace has no plane, but the
//      traces of one set on one face run parallel, along n_set x n_face),
//      nearest within kTraceDirectionDeg,
// and is otherwise random (it counts in Jv's random term and in Jn's
// "plus random").
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/rockmass/face_window.h"

namespace rockface::rockmass {

struct SetInput {
  std::string label;                                  // "S1"
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // mean pole
};

struct SetTraces {
  std::vector<std::vector<int>> members;  // per set (input order): trace indices
  std::vector<int> random;                // traces of no set
  std::vector<int> set_of;                // per trace: set index or -1
  std::vector<std::string> how;           // per trace: why it went where it went
};

SetTraces assign_traces_to_sets(const std::vector<FaceTrace>& traces,
                                const std::vector<SetInput>& sets, const FaceWindow& window);

// Angle (degrees, [0, 90]) between two axes (n and -n the same).
double axial_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace rockface::rockmass
