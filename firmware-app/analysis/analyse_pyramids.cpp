// Joint pyramids of the scene's joints against each free face, or each group
// of free faces forming a convex corner or edge of the excavation.
#include <map>

#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/joint_pyramids.h"
#include "firmware-app/analysis/scene_analysis.h"

namespace rockface::app {

namespace {

storage::ReportMode report_mode(const kinematics::SlidingMode& m, const AnalysisInput& scene) {
  storage::ReportMode r;
  r.type = kinematics::mode_name(m.type);
  for (int p : m.planes) r.planes.push_back(scene.joints[p].id);
  if (m.type != kinematics::ModeType::None) r.direction = m.direction;
  r.marginal = m.marginal;
  return r;
}

}  // namespace

void analyse_pyramids(const AnalysisInput& scene, storage::Report& report) {
  std::vector<kinematics::JointSpec> joints;
  for (const auto& j : scene.joints) {
    kinematics::JointSpec spec{geometry::plane_normal_deg(j.dip, j.dipdir), std::nullopt};
    if (j.friction) spec.friction = deg_to_rad(*j.friction);
    joints.push_back(spec);
  }
  // Faces sharing a group are one excavation pyramid; the others one each,
  // in scene order of their first face.
  std::vector<std::pair<std::string, std::vector<kinematics::FreeFaceSpec>>> pyramids;
  std::map<std::string, size_t> group_index;
  for (const auto& f : scene.free_faces) {
    const kinematics::FreeFaceSpec spec{
        geometry::plane_normal_deg(f.dip, f.dipdir),
        f.rock_side == 0 ? geometry::HalfSpace::Upper : geometry::HalfSpace::Lower};
    if (f.group.empty()) {
      pyramids.push_back({f.id, {spec}});
    } else if (auto it = group_index.find(f.group); it != group_index.end()) {
      pyramids[it->second].second.push_back(spec);
    } else {
      group_index[f.group] = pyramids.size();
      pyramids.push_back({f.group, {spec}});
    }
  }

  // Active resultant. Pyramids have no mass: gravity and seismic act per unit
  // mass; point forces need the reference mass the scene may give.
  kinematics::PyramidOptions options;
  options.uncertainty = deg_to_rad(scene.analysis.orientation_uncertainty_deg);
  Eigen::Vector3d per_mass = scene.gravity;
  if (scene.effects.seismic) per_mass += *scene.effects.seismic;
  if (scene.analysis.reference_mass) {
    options.resultant = *scene.analysis.reference_mass * per_mass;
    for (const auto& f : scene.effects.forces) options.resultant += f.vector;
  } else {
    options.resultant = per_mass;
    if (!scene.effects.forces.empty())
      report.notes.push_back(
          "pyramids: effects.forces not applied (a pyramid has no mass to weigh them against; give "
          "analysis.reference_mass in kg)");
  }
  if (!scene.effects.bolts.empty() || scene.effects.water)
    report.notes.push_back(
        "pyramids: water and bolts act on blocks with faces and positions, not on pyramids");

  for (const auto& [name, faces] : pyramids) {
    const geometry::Cone ep = kinematics::excavation_pyramid(faces);
    for (const auto& v : kinematics::analyse_joint_pyramids(joints, ep, options)) {
      storage::ReportPyramid p;
      p.face = name;
      p.code = v.code_text;
      p.empty = v.empty;
      p.finite = v.finite;
      p.removable = v.removable.value;
      p.margin_deg = rad_to_deg(v.removable.margin);
      p.marginal = v.removable.marginal;
      p.jp_margin_deg = rad_to_deg(v.jp_margin);
      p.jp_ep_margin_deg = rad_to_deg(v.jp_ep_margin);
      if (v.mode) {
        p.mode = report_mode(*v.mode, scene);
        p.fos = v.mode->fos;
      }
      report.pyramids.push_back(std::move(p));
    }
  }
}

}  // namespace rockface::app
