#include "firmware-app/analysis/scene_input.h"

#include "core/tunnel/alignment.h"

namespace rockface::app {

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
  return analysis::tunnel_invert_floor(alignment, t.record.profile, chainage, datum);
}

analysis::AnalysisInput analysis_input(const storage::Scene& scene) {
  analysis::AnalysisInput in;
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
