#include "core/analysis/analysis_input.h"

#include <algorithm>

#include "core/common/units.h"
#include "core/geometry/orientation.h"

namespace rockface::analysis {

const SceneJoint* AnalysisInput::joint(const std::string& id) const {
  const auto j =
      std::find_if(joints.begin(), joints.end(), [&](const auto& p) { return p.id == id; });
  return j == joints.end() ? nullptr : &*j;
}

int AnalysisInput::plane_index(const std::string& id) const {
  const auto named = [&](const auto& plane) { return plane.id == id; };
  if (const auto j = std::find_if(joints.begin(), joints.end(), named); j != joints.end())
    return static_cast<int>(j - joints.begin());
  if (const auto f = std::find_if(free_faces.begin(), free_faces.end(), named);
      f != free_faces.end())
    return static_cast<int>(joints.size()) + static_cast<int>(f - free_faces.begin());
  return -1;
}

SceneFloor tunnel_invert_floor(const tunnel::Alignment& alignment,
                               const tunnel::DesignProfile& profile, double chainage,
                               const Eigen::Vector3d& datum) {
  // The outline's lowest point, every centimetre.
  Eigen::Vector2d lowest = profile.point_at_length(0);
  for (double s = 0; s < profile.perimeter(); s += 0.01) {
    const Eigen::Vector2d p = profile.point_at_length(s);
    if (p.y() < lowest.y()) lowest = p;
  }
  const tunnel::TunnelFrame frame = alignment.frame_at(chainage);
  SceneFloor floor;
  floor.point = frame.to_local(lowest.x(), lowest.y()) + datum;
  const geometry::PlaneOrientation o = geometry::plane_orientation(frame.up);
  floor.dip = rad_to_deg(o.dip);
  floor.dipdir = rad_to_deg(o.dipdir);
  return floor;
}

std::vector<std::string> SceneEffects::listed() const {
  std::vector<std::string> names{"gravity"};
  if (water) names.push_back("water");
  if (seismic) names.push_back("seismic");
  if (insitu_stress) names.push_back("insitu_stress");
  if (!forces.empty()) names.push_back("forces");
  if (!bolts.empty()) names.push_back("bolts");
  if (joint_law) names.push_back("joint_law");
  return names;
}

}  // namespace rockface::analysis
