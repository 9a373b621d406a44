#include "core/analysis/analyse_rock_mass.h"

#include <map>

#include "core/common/error.h"
#include "core/geometry/orientation.h"
#include "core/measure/joint_sets.h"
#include "core/rockmass/rock_mass_figures.h"

namespace rockface::analysis {

void analyse_rock_mass(const AnalysisInput& scene, Report& report) {
  rockmass::RockMassInput in;
  // The sets: the joints' planes clustered (core/measure, automatic count).
  std::map<std::string, std::string> set_of_joint;
  if (scene.joints.size() >= 2) {
    std::vector<Eigen::Vector3d> poles;
    for (const auto& j : scene.joints) poles.push_back(geometry::plane_normal_deg(j.dip, j.dipdir));
    const measure::PoleClusters c = measure::cluster_poles(poles, {});
    for (std::size_t k = 0; k < c.sets.size(); ++k)
      in.sets.push_back({"S" + std::to_string(k + 1), c.sets[k].mean});
    for (std::size_t i = 0; i < scene.joints.size(); ++i)
      if (c.set_of[i] >= 0) set_of_joint[scene.joints[i].id] = in.sets[c.set_of[i]].label;
  }
  // Datum-relative: survey coordinates of 10^6 m lose no precision.
  for (const auto& t : scene.traces) {
    if (t.points.size() < 2) continue;
    rockmass::FaceTrace f;
    f.label = t.id;
    f.joint_label = t.joint.value_or("");
    if (const auto s = set_of_joint.find(f.joint_label); s != set_of_joint.end())
      f.set_label = s->second;
    for (const auto& p : t.points) f.points.push_back(p - scene.datum);
    in.traces.push_back(std::move(f));
  }
  for (const auto& b : report.blocks)
    if (b.source == "traces" && b.finite && b.volume && *b.volume > 0)
      in.blocks.push_back({b.id, *b.volume, b.principal_moments, b.mass});
  if (scene.rockmass_form) in.form = *scene.rockmass_form;
  try {
    report.rockmass = rockmass::rock_mass_figures(in);
  } catch (const InputError& e) {
    if (e.where() != "face") throw InputError(scene.source + ": rockmass." + e.where(), e.reason());
    report.notes.push_back("rock mass: " + e.reason());
  }
}

}  // namespace rockface::analysis
