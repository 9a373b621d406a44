#include "storage/office/server_drive.h"

#include <algorithm>
#include <cstdlib>
#include <map>

#include "core/common/error.h"
#include "storage/office/server_records.h"

namespace rockface::storage::office {

namespace {

// The latest live revision of each record of one kind in the tunnel, with
// the given fields of its row as text.
Result latest(Connection& c, std::int64_t tunnel, const std::string& kind,
              const std::vector<std::string>& fields) {
  std::string select = "SELECT visit_uuid::text, project_uuid::text, local_id";
  for (const auto& f : fields) select += ", body->'row'->>'" + f + "'";
  return c.query(select +
                     " FROM (SELECT DISTINCT ON (kind, uuid) * FROM rockface.record WHERE "
                     "tunnel_id = $1 AND kind = $2 ORDER BY kind, uuid, revision DESC) l "
                     "WHERE NOT deleted ORDER BY visit_uuid, local_id",
                 {Param::of(tunnel), Param::of(kind)}, "reading the drive's " + kind + " records");
}

double number(const Result& r, int row, int column) {
  return std::strtod(r.text(row, column).c_str(), nullptr);
}

}  // namespace

ServerDrive read_server_drive(Connection& c, const std::string& name) {
  c.exec("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY", "reading the drive");
  const ServerTunnel t = read_server_tunnel(c, name);
  ServerDrive out;
  std::map<std::string, RecordId> ids;
  for (std::size_t i = 0; i < t.visits.size(); ++i)
    ids[t.visits[i].uuid] =
        t.projects.size() == 1 ? t.visits[i].local_id : static_cast<RecordId>(i + 1);

  const Result tunnels = latest(c, t.id, "tunnel", {"drive"});
  if (tunnels.rows() == 0)
    throw InputError("tunnel " + name,
                     "no tablet has sent the tunnel's alignment and design profile yet");
  // The first project's tunnel, as a pull keeps it.
  int pick = 0;
  for (int i = 0; i < tunnels.rows(); ++i)
    if (!t.projects.empty() && tunnels.text(i, 1) == t.projects.front()) pick = i;
  out.drive = tunnel::drive_of(tunnels.text(pick, 3), "tunnel " + name + " drive");

  std::map<std::string, DriveVisitRecords> visits;
  const Result placements = latest(c, t.id, "visit_placement", {"chainage"});
  for (int i = 0; i < placements.rows(); ++i) {
    const std::string v = placements.text(i, 0);
    DriveVisitRecords& d = visits[v];
    d.visit_id = ids.at(v);
    d.chainage = number(placements, i, 3);
  }
  const Result sets = latest(c, t.id, "joint_set", {"label", "dip", "dipdir", "fisher_k", "count"});
  for (int i = 0; i < sets.rows(); ++i) {
    const auto it = visits.find(sets.text(i, 0));
    if (it == visits.end()) continue;
    JointSet s;
    s.label = sets.text(i, 3);
    s.dip_deg = number(sets, i, 4);
    s.dipdir_deg = number(sets, i, 5);
    s.fisher_k = number(sets, i, 6);
    s.count = static_cast<int>(sets.int64(i, 7));
    it->second.sets.push_back(std::move(s));
  }
  const Result planes = latest(c, t.id, "measurement", {"dip", "dipdir"});
  for (int i = 0; i < planes.rows(); ++i) {
    const auto it = visits.find(planes.text(i, 0));
    if (it == visits.end()) continue;
    Measurement m;
    if (!planes.is_null(i, 3)) m.dip_deg = number(planes, i, 3);
    if (!planes.is_null(i, 4)) m.dipdir_deg = number(planes, i, 4);
    it->second.measurements.push_back(std::move(m));
  }
  const Result geologists = latest(c, t.id, "visit_geologist", {"geologist"});
  for (int i = 0; i < geologists.rows(); ++i) {
    const auto it = visits.find(geologists.text(i, 0));
    if (it != visits.end() && !geologists.is_null(i, 3))
      it->second.geologist = geologists.text(i, 3);
  }
  c.exec("COMMIT", "reading the drive");
  for (auto& [uuid, v] : visits) out.visits.push_back(std::move(v));
  std::sort(out.visits.begin(), out.visits.end(), [](const auto& a, const auto& b) {
    return a.chainage != b.chainage ? a.chainage < b.chainage : a.visit_id < b.visit_id;
  });
  return out;
}

}  // namespace rockface::storage::office
