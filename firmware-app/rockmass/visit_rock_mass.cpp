#include "firmware-app/rockmass/visit_rock_mass.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/common/error.h"
#include "core/geometry/orientation.h"
#include "core/measure/joint_sets.h"
#include "core/tunnel/strike_vs_drive.h"
#include "firmware-app/tunnel/project_drive.h"

namespace rockface::app {

namespace {

using rockmass::SetInput;

// The sets and, per joint label, the set it belongs to.
struct VisitSets {
  std::vector<SetInput> sets;
  std::map<std::string, std::string> set_of_joint;
};

VisitSets visit_sets(storage::ProjectStore& store, storage::RecordId visit_id) {
  VisitSets out;
  const auto joints = store.list_joints(visit_id);
  for (const auto& s : store.list_joint_sets(visit_id))
    out.sets.push_back({s.label, geometry::plane_normal_deg(s.dip_deg, s.dipdir_deg)});
  if (!out.sets.empty()) {
    for (const auto& j : joints)
      if (!j.set_label.empty()) out.set_of_joint[j.label] = j.set_label;
    return out;
  }
  // No sets stored: the joints' planes clustered (core/measure, automatic
  // count) when there are two or more, else the measured planes'.
  if (joints.size() >= 2) {
    std::vector<Eigen::Vector3d> poles;
    for (const auto& j : joints)
      poles.push_back(geometry::plane_normal_deg(j.dip_deg, j.dipdir_deg));
    const measure::PoleClusters c = measure::cluster_poles(poles, {});
    for (std::size_t k = 0; k < c.sets.size(); ++k)
      out.sets.push_back({"S" + std::to_string(k + 1), c.sets[k].mean});
    for (std::size_t i = 0; i < joints.size(); ++i)
      if (c.set_of[i] >= 0) out.set_of_joint[joints[i].label] = out.sets[c.set_of[i]].label;
    return out;
  }
  for (const auto& s : visit_set_observations(store, visit_id))
    out.sets.push_back({s.name, s.normal});
  return out;
}

// The finite blocks of the visit's latest analysis, with their principal
// moments and mass from the block's report.
std::vector<rockmass::FaceBlock> visit_blocks(storage::ProjectStore& store,
                                              storage::RecordId visit_id) {
  std::vector<rockmass::FaceBlock> out;
  const auto runs = store.list_analyses(visit_id);
  if (runs.empty()) return out;
  const auto latest = std::max_element(runs.begin(), runs.end(),
                                       [](const auto& a, const auto& b) { return a.id < b.id; });
  for (const auto& b : store.load_analysis(latest->id).blocks) {
    const double volume = b.volume.value_or(0);
    if (!b.finite || !(volume > 0)) continue;
    rockmass::FaceBlock fb{b.id, volume, std::nullopt, std::nullopt};
    // Both known (a null in the stored report reads as NaN): else the block
    // counts by its volume alone.
    if (b.principal_moments && b.principal_moments->allFinite() && b.mass && !std::isnan(*b.mass)) {
      fb.principal_moments = *b.principal_moments;
      fb.mass_kg = *b.mass;
    }
    out.push_back(fb);
  }
  return out;
}

rockmass::OrientationClass orientation_of(tunnel::DriveClass c) {
  return static_cast<rockmass::OrientationClass>(static_cast<int>(c));  // same order, same table
}

// The design profile's width (its span), from points along its outline.
double profile_width(const tunnel::DesignProfile& p) {
  double lo = 1e300, hi = -1e300;
  const int n = 720;
  for (int i = 0; i <= n; ++i) {
    const double u = p.point_at_length(p.perimeter() * i / n).x();
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  return hi - lo;
}

}  // namespace

RockMassProject rock_mass_project(storage::ProjectStore& store) {
  RockMassProject out;
  for (const auto& v : store.list_visits()) out.visits.insert(v.id);
  if (const auto tunnel = store.load_tunnel()) {
    out.alignment = tunnel->alignment(store.project().datum);
    out.tunnel_span_m = profile_width(tunnel->profile);
  }
  return out;
}

rockmass::RockMassInput visit_rock_mass_input(
    storage::ProjectStore& store, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& form) {
  return visit_rock_mass_input(store, rock_mass_project(store), visit_id, form);
}

rockmass::RockMassInput visit_rock_mass_input(
    storage::ProjectStore& store, const RockMassProject& project, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& form) {
  if (!project.visits.count(visit_id))
    throw InputError("--visit", "the project " + store.file().string() + " has no visit " +
                                    std::to_string(visit_id));
  rockmass::RockMassInput in;
  const VisitSets sets = visit_sets(store, visit_id);
  in.sets = sets.sets;

  std::vector<Eigen::Vector3d> trace_points;
  for (const auto& m : store.list_measurements(visit_id)) {
    if (m.kind != storage::Measurement::Kind::trace || m.points.size() < 2) continue;
    rockmass::FaceTrace t;
    t.label = m.label;
    t.joint_label = m.joint_label;
    t.points = m.points;
    if (m.dip_deg && m.dipdir_deg) t.normal = geometry::plane_normal_deg(*m.dip_deg, *m.dipdir_deg);
    const auto set = sets.set_of_joint.find(m.joint_label);
    if (set != sets.set_of_joint.end()) t.set_label = set->second;
    t.length_m = m.trace_length_m;
    t.censored = m.censored;
    trace_points.insert(trace_points.end(), m.points.begin(), m.points.end());
    in.traces.push_back(std::move(t));
  }
  if (in.traces.empty())
    throw InputError("--visit", "visit " + std::to_string(visit_id) +
                                    " has no traces: map the joints' traces on the face first");

  // The sampling window is where traces were mapped: the hull of the
  // traces' points (a free-face area beyond them was not mapped for joints,
  // and counting it would dilute every frequency).
  in.outline_points = trace_points;
  in.blocks = visit_blocks(store, visit_id);

  // The sets against the drive, where the visit is placed in a tunnel.
  if (project.alignment) {
    if (const auto placement = store.load_visit_placement(visit_id)) {
      const Eigen::Vector3d drive = project.alignment->tangent_at(placement->chainage);
      for (const auto& s : in.sets) {
        const tunnel::StrikeVsDrive c = tunnel::strike_vs_drive(s.normal, drive);
        in.drive.push_back({s.label, orientation_of(c.cls), c.words, c.margin_deg, c.marginal});
      }
      in.tunnel_span_m = project.tunnel_span_m;
    }
  }
  if (form)
    in.form = *form;
  else if (const auto stored = store.load_rockmass_form(visit_id))
    in.form = *stored;
  return in;
}

rockmass::RockMassFigures visit_rock_mass(storage::ProjectStore& store, storage::RecordId visit_id,
                                          const std::optional<rockmass::ClassificationForm>& form) {
  return rockmass::rock_mass_figures(visit_rock_mass_input(store, visit_id, form));
}

rockmass::RockMassFigures visit_rock_mass(storage::ProjectStore& store,
                                          const RockMassProject& project,
                                          storage::RecordId visit_id) {
  return rockmass::rock_mass_figures(visit_rock_mass_input(store, project, visit_id));
}

}  // namespace rockface::app
