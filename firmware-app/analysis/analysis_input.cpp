#include "firmware-app/analysis/analysis_input.h"

#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/tunnel/alignment.h"

#include <algorithm>

namespace rockface::app {

const analysis::SceneJoint* AnalysisInput::joint(const std::string& id) const {
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

analysis::SceneFloor tunnel_invert_floor(const storage::Scene& scene) {
  const storage::SceneTunnel& t = *scene.tunnel;
  const Eigen::Vector3d datum = scene.has_datum ? scene.datum : Eigen::Vector3d::Zero();
  const tunnel::Alignment alignment = t.record.alignment(datum);
  // The face: the rendered round's, else the typed pole's chainage, else the
  // middle of the alignment.
  const double chainage = t.render ? t.render->face_chainage
                          : t.placement
                              ? t.placement->chainage
                              : 0.5 * (alignment.first_chainage() + alignment.last_chainage());
  // The outline's lowest point, every centimetre.
  const tunnel::DesignProfile& profile = t.record.profile;
  Eigen::Vector2d lowest = profile.point_at_length(0);
  for (double s = 0; s < profile.perimeter(); s += 0.01) {
    const Eigen::Vector2d p = profile.point_at_length(s);
    if (p.y() < lowest.y()) lowest = p;
  }
  const tunnel::TunnelFrame frame = alignment.frame_at(chainage);
  analysis::SceneFloor floor;
  floor.point = frame.to_local(lowest.x(), lowest.y()) + datum;
  const geometry::PlaneOrientation o = geometry::plane_orientation(frame.up);
  floor.dip = rad_to_deg(o.dip);
  floor.dipdir = rad_to_deg(o.dipdir);
  return floor;
}

AnalysisInput analysis_input(const storage::Scene& scene) {
  AnalysisInput in;
  in.source = scene.source;
  in.datum = scene.datum;
  in.has_datum = scene.has_datum;
  in.density = scene.density;
  in.gravity = scene.gravity;
  in.joints = scene.joints;
  in.free_faces = scene.free_faces;
  in.blocks = scene.blocks;
  in.patches = scene.patches;
  in.traces = scene.traces;
  in.analysis = scene.analysis;
  in.effects = scene.effects;
  in.rockmass_form = scene.rockmass;
  // In a tunnel a block in free flight lands on the invert: the design
  // profile's lowest point at the face, when the scene gives no floor.
  if (in.analysis.dynamics && !in.analysis.dynamics->floor && scene.tunnel)
    in.analysis.dynamics->floor = tunnel_invert_floor(scene);
  return in;
}

}  // namespace rockface::app
