#include "firmware-app/tunnel/project_drive.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <utility>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/measure/joint_sets.h"
#include "storage/exchange/csv_record.h"
#include "storage/field_report/field_report.h"
#include "storage/project/visit_geologist.h"

namespace rockface::app {

namespace {

const std::string& geologist_of(const DriveGeologists& geologists, std::int64_t visit_id) {
  static const std::string none = storage::kGeologistNotRecorded;
  const auto it = geologists.find(visit_id);
  return it == geologists.end() ? none : it->second;
}

}  // namespace

std::vector<tunnel::SetObservation> visit_set_observations(storage::ProjectStore& store,
                                                           storage::RecordId visit_id) {
  return set_observations(store.list_joint_sets(visit_id), store.list_measurements(visit_id));
}

std::vector<tunnel::SetObservation> set_observations(
    const std::vector<storage::JointSet>& sets,
    const std::vector<storage::Measurement>& measurements) {
  std::vector<tunnel::SetObservation> out;
  for (const auto& s : sets)
    out.push_back(
        {s.label, geometry::plane_normal_deg(s.dip_deg, s.dipdir_deg), s.fisher_k, s.count});
  if (!out.empty()) return out;
  std::vector<Eigen::Vector3d> poles;
  for (const auto& m : measurements)
    if (m.dip_deg && m.dipdir_deg)
      poles.push_back(geometry::plane_normal_deg(*m.dip_deg, *m.dipdir_deg));
  if (poles.size() < 2) return out;
  const measure::PoleClusters clusters = measure::cluster_poles(poles, {});
  for (std::size_t k = 0; k < clusters.sets.size(); ++k) {
    const auto& f = clusters.sets[k];
    out.push_back({"S" + std::to_string(k + 1), f.mean, f.kappa, static_cast<int>(f.count)});
  }
  return out;
}

std::vector<JointOrientation> visit_joint_orientations(storage::ProjectStore& store,
                                                       storage::RecordId visit_id) {
  std::vector<JointOrientation> out;
  for (const auto& j : store.list_joints(visit_id))
    out.push_back({j.label, j.dip_deg, j.dipdir_deg});
  if (!out.empty()) return out;
  for (const auto& m : store.list_measurements(visit_id))
    if (m.kind != storage::Measurement::Kind::area && m.dip_deg && m.dipdir_deg)
      out.push_back({m.label, *m.dip_deg, *m.dipdir_deg});
  return out;
}

tunnel::DriveSets project_drive(storage::ProjectStore& store) {
  const auto tunnel = store.load_tunnel();
  if (!tunnel)
    throw InputError(store.file().string(),
                     "the project has no tunnel: add its alignment and design profile first");
  std::vector<tunnel::VisitSets> visits;
  for (const auto& p : store.list_visit_placements())
    visits.push_back({p.visit_id, p.chainage, visit_set_observations(store, p.visit_id)});
  tunnel::DriveSetOptions options;
  options.drive = tunnel->drive;
  return tunnel::track_sets_along_drive(std::move(visits), options);
}

DriveGeologists drive_geologists(storage::ProjectStore& store) {
  std::set<storage::RecordId> placed;
  for (const auto& p : store.list_visit_placements()) placed.insert(p.visit_id);
  DriveGeologists out;
  for (const auto& v : store.list_visits())
    if (v.geologist && placed.count(v.id)) out[v.id] = *v.geologist;
  return out;
}

std::string drive_csv(const tunnel::DriveSets& drive, const DriveGeologists& geologists) {
  std::ostringstream out;
  // The geologist last: the columns before keep their places for the
  // spreadsheets that read them (docs/scene-extensions.md).
  out << "set,visit,chainage,name,dip_deg,dipdir_deg,fisher_k,count,alpha95_deg,"
         "angle_to_running_mean_deg,turn_cone_deg,event,geologist\n";
  for (const auto& t : drive.tracks) {
    for (const auto& p : t.points) {
      std::string event = p.turned ? "turns" : "";
      for (const auto& e : t.events)
        if (e.visit_id == p.visit_id && e.kind == tunnel::TrackEvent::Kind::appears)
          event = event.empty() ? "appears" : event + " appears";
      out << t.id << "," << p.visit_id << "," << storage::report_number(p.chainage, 3) << ","
          << p.name << "," << storage::report_number(p.dip_deg, 1) << ","
          << storage::report_number(p.dipdir_deg, 1) << "," << storage::report_number(p.fisher_k, 1)
          << "," << p.count << ","
          << (p.alpha95_deg < 180 ? storage::report_number(p.alpha95_deg, 1) : "") << ","
          << storage::report_number(p.angle_to_running_mean_deg, 1) << ","
          << storage::report_number(p.turn_cone_deg, 1) << "," << event << ","
          << storage::csv_field(geologist_of(geologists, p.visit_id)) << "\n";
    }
    for (const auto& e : t.events)
      if (e.kind == tunnel::TrackEvent::Kind::vanishes)
        out << t.id << "," << e.visit_id << "," << storage::report_number(e.chainage, 3)
            << ",,,,,,,,,vanishes," << storage::csv_field(geologist_of(geologists, e.visit_id))
            << "\n";
  }
  return out.str();
}

std::vector<std::string> drive_summary(const tunnel::DriveSets& drive,
                                       const DriveGeologists& geologists) {
  std::vector<std::string> lines;
  lines.push_back(std::to_string(drive.visits.size()) + " visits placed in the tunnel, " +
                  std::to_string(drive.tracks.size()) + " joint sets along the drive");
  // Who mapped them, in the order they first mapped along the drive.
  std::vector<std::pair<std::string, int>> mapped;
  for (const auto& v : drive.visits) {
    const std::string name = geologist_of(geologists, v.visit_id);
    auto it =
        std::find_if(mapped.begin(), mapped.end(), [&](const auto& m) { return m.first == name; });
    if (it == mapped.end()) it = mapped.insert(mapped.end(), {name, 0});
    ++it->second;
  }
  if (!mapped.empty()) {
    std::string line = "geologists:";
    for (std::size_t i = 0; i < mapped.size(); ++i)
      line += std::string(i ? "," : "") + " " + mapped[i].first + " (" +
              std::to_string(mapped[i].second) + (mapped[i].second == 1 ? " visit)" : " visits)");
    lines.push_back(line);
  }
  for (const auto& t : drive.tracks) {
    const auto& a = t.points.front();
    const auto& b = t.points.back();
    lines.push_back(
        "set " + std::to_string(t.id) + ": " + std::to_string(t.points.size()) +
        " visits, chainage " + storage::report_number(a.chainage, 2) + " to " +
        storage::report_number(b.chainage, 2) + ", " + storage::report_number(a.dip_deg, 0) + "/" +
        storage::report_number(a.dipdir_deg, 0) + " to " + storage::report_number(b.dip_deg, 0) +
        "/" + storage::report_number(b.dipdir_deg, 0));
    for (const auto& e : t.events)
      lines.push_back("  " + e.message + " (geologist: " + geologist_of(geologists, e.visit_id) +
                      ")");
  }
  return lines;
}

}  // namespace rockface::app
