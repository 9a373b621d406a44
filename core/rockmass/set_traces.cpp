#include "core/rockmass/set_traces.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/common/number_format.h"
#include "core/rockmass/tolerances.h"

namespace rockface::rockmass {

double axial_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = std::min(1.0, std::abs(a.normalized().dot(b.normalized())));
  return std::acos(c) * 180.0 / M_PI;
}

SetTraces assign_traces_to_sets(const std::vector<FaceTrace>& traces,
                                const std::vector<SetInput>& sets, const FaceWindow& window) {
  SetTraces out;
  out.members.resize(sets.size());
  out.set_of.assign(traces.size(), -1);
  out.how.resize(traces.size());
  for (std::size_t i = 0; i < traces.size(); ++i) {
    const FaceTrace& t = traces[i];
    int chosen = -1;
    for (std::size_t k = 0; k < sets.size() && chosen < 0; ++k)
      if (!t.set_label.empty() && t.set_label == sets[k].label) {
        chosen = static_cast<int>(k);
        out.how[i] = "its joint's set " + sets[k].label;
      }
    if (chosen < 0 && t.normal) {
      double best = kSetMemberDeg;
      for (std::size_t k = 0; k < sets.size(); ++k) {
        const double a = axial_angle_deg(*t.normal, sets[k].normal);
        if (a <= best) {
          best = a;
          chosen = static_cast<int>(k);
        }
      }
      if (chosen >= 0) {
        out.how[i] = "its plane, " + format_fixed(best, 1, " deg") + " from " + sets[chosen].label;
      }
    }
    if (chosen < 0 && t.points.size() >= 2) {
      const Eigen::Vector3d d = t.points.back() - t.points.front();
      double best = kTraceDirectionDeg;
      for (std::size_t k = 0; k < sets.size(); ++k) {
        const Eigen::Vector3d along = sets[k].normal.cross(window.normal);
        if (along.norm() < 1e-9 || d.norm() <= 0) continue;  // a set parallel to the face
        const double a = axial_angle_deg(d, along);
        if (a <= best) {
          best = a;
          chosen = static_cast<int>(k);
        }
      }
      if (chosen >= 0) {
        out.how[i] = "its direction on the face, " + format_fixed(best, 1, " deg") + " from " +
                     sets[chosen].label + "'s traces";
      }
    }
    if (chosen < 0) {
      out.random.push_back(static_cast<int>(i));
      out.how[i] = "random: no set by joint, plane or direction";
    } else {
      out.members[chosen].push_back(static_cast<int>(i));
    }
    out.set_of[i] = chosen;
  }
  return out;
}

}  // namespace rockface::rockmass
