// Joint pyramids of the scene's joints against each free face, or each group
// of free faces forming a convex corner or edge of the excavation. A face
// mapped trace by trace has a plane per trace: beyond kMaxPyramidJoints the
// table of 2^n codes is built over the joints' sets instead (the blocks from
// traces still take every plane).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/analysis/scene_analysis.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/joint_pyramids.h"
#include "core/measure/joint_sets.h"

namespace rockface::analysis {

namespace {

// 2^12 codes take a quarter of a second (docs/accuracy-cost.md, "Joint
// pyramids"), and each further joint doubles it: more joints than this are
// grouped into sets for the table.
constexpr size_t kMaxPyramidJoints = 12;

// The planes the table's code digits stand for: the joints, or their sets.
struct PyramidPlanes {
  std::vector<kinematics::JointSpec> specs;
  std::vector<std::string> names;
};

std::string degrees(double radians) {
  return std::to_string(static_cast<int>(std::lround(rad_to_deg(radians))));
}

PyramidPlanes joint_planes(const AnalysisInput& scene) {
  PyramidPlanes planes;
  for (const auto& j : scene.joints) {
    kinematics::JointSpec spec{geometry::plane_normal_deg(j.dip, j.dipdir), std::nullopt};
    if (j.friction) spec.friction = deg_to_rad(*j.friction);
    planes.specs.push_back(spec);
    planes.names.push_back(j.id);
  }
  return planes;
}

// The joints clustered into sets (measure::cluster_poles, automatic count):
// each set's Fisher mean plane, and the least friction of its members (the
// weakest joint of a set is the one a block slides on). The report's notes
// say which joints make each set, and which fall in none (left out).
PyramidPlanes set_planes(const AnalysisInput& scene, Report& report) {
  std::vector<Eigen::Vector3d> poles;
  for (const auto& j : scene.joints) poles.push_back(geometry::plane_normal_deg(j.dip, j.dipdir));
  const measure::PoleClusters clusters = measure::cluster_poles(poles, {});
  PyramidPlanes planes;
  std::ostringstream note;
  note << "pyramids: " << scene.joints.size() << " joints, more than " << kMaxPyramidJoints
       << " (2^n codes): the table is over their " << clusters.sets.size()
       << " joint sets, each set's mean plane and its members' least friction; the blocks from "
          "traces take every joint";
  std::string left_out;
  for (size_t s = 0; s < clusters.sets.size(); ++s) {
    const std::string name = "S" + std::to_string(s + 1);
    kinematics::JointSpec spec{clusters.sets[s].mean, std::nullopt};
    std::string members;
    for (size_t j = 0; j < scene.joints.size(); ++j) {
      if (clusters.set_of[j] != static_cast<int>(s)) continue;
      members += (members.empty() ? "" : ", ") + scene.joints[j].id;
      if (const auto& f = scene.joints[j].friction)
        spec.friction = std::min(spec.friction.value_or(deg_to_rad(*f)), deg_to_rad(*f));
    }
    const geometry::PlaneOrientation o = clusters.sets[s].plane();
    note << "; " << name << " " << degrees(o.dip) << "/" << degrees(o.dipdir) << " ("
         << clusters.sets[s].count << " joints: " << members << ")";
    planes.specs.push_back(spec);
    planes.names.push_back(name);
  }
  for (size_t j = 0; j < scene.joints.size(); ++j)
    if (clusters.set_of[j] < 0) left_out += (left_out.empty() ? "" : ", ") + scene.joints[j].id;
  if (!left_out.empty()) note << "; in no set, so not in the table: " << left_out;
  report.notes.push_back(note.str());
  return planes;
}

ReportMode report_mode(const kinematics::SlidingMode& m, const PyramidPlanes& planes) {
  ReportMode r;
  r.type = kinematics::mode_name(m.type);
  for (int p : m.planes) r.planes.push_back(planes.names[p]);
  if (m.type != kinematics::ModeType::None) r.direction = m.direction;
  r.marginal = m.marginal;
  return r;
}

}  // namespace

void analyse_pyramids(const AnalysisInput& scene, Report& report) {
  const PyramidPlanes planes =
      scene.joints.size() <= kMaxPyramidJoints ? joint_planes(scene) : set_planes(scene, report);
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
    for (const auto& v : kinematics::analyse_joint_pyramids(planes.specs, ep, options)) {
      ReportPyramid p;
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
        p.mode = report_mode(*v.mode, planes);
        p.fos = v.mode->fos;
      }
      report.pyramids.push_back(std::move(p));
    }
  }
}

}  // namespace rockface::analysis
