#include "storage/office/server_records.h"

#include <cstdlib>
#include <set>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/project/project_schema.h"

namespace rockface::storage::office {

ServerTunnel read_server_tunnel(Connection& c, const std::string& name) {
  ServerTunnel t;
  t.name = name;
  const Result r = c.query("SELECT id FROM rockface.tunnel WHERE name = $1", {Param::of(name)},
                           "finding the tunnel");
  if (r.rows() == 0)
    throw InputError("tunnel " + name, "not on " + c.label() + ", or this role may not read it");
  t.id = r.int64(0, 0);
  const Result p = c.query(
      "SELECT uuid::text FROM rockface.project WHERE tunnel_id = $1 ORDER BY first_synced_at, uuid",
      {Param::of(t.id)}, "reading the tunnel's projects");
  for (int i = 0; i < p.rows(); ++i) t.projects.push_back(p.text(i, 0));
  const Result v = c.query(
      "SELECT uuid::text, project_uuid::text, local_id FROM rockface.visit WHERE tunnel_id = $1 "
      "ORDER BY started_at, project_uuid, local_id",
      {Param::of(t.id)}, "reading the tunnel's visits");
  for (int i = 0; i < v.rows(); ++i)
    t.visits.push_back({v.text(i, 0), v.text(i, 1), v.int64(i, 2)});
  return t;
}

namespace {

// The rows of a latest-records query (kind, uuid, visit, project, local id,
// schema, body); a record of a newer project schema is refused by name.
std::vector<ServerRecord> records_of(const Result& r) {
  std::vector<ServerRecord> out;
  out.reserve(static_cast<std::size_t>(r.rows()));
  for (int i = 0; i < r.rows(); ++i) {
    ServerRecord rec{r.text(i, 0), r.text(i, 1),  r.optional_text(i, 2),
                     r.text(i, 3), r.int64(i, 4), static_cast<int>(r.int64(i, 5)),
                     r.text(i, 6)};
    if (rec.project_schema > schema::kCurrentVersion)
      throw InputError(rec.kind + " " + rec.uuid,
                       "written by a newer rockface (project schema " +
                           std::to_string(rec.project_schema) + ", this program knows up to " +
                           std::to_string(schema::kCurrentVersion) + "): update rockface");
    out.push_back(std::move(rec));
  }
  return out;
}

}  // namespace

std::vector<ServerRecord> read_current_records(Connection& c, std::int64_t tunnel_id,
                                               const std::vector<std::string>& kinds,
                                               bool with_body) {
  std::string list = "{";
  for (std::size_t i = 0; i < kinds.size(); ++i) list += (i ? "," : "") + kinds[i];
  list += "}";
  // DISTINCT ON inside the tunnel's rows (record_by_tunnel_kind), not over
  // the view, whose DISTINCT ON would run over every tunnel first.
  const Result r =
      c.query(std::string("SELECT kind, uuid::text, visit_uuid::text, project_uuid::text, "
                          "coalesce(local_id, 0), project_schema, ") +
                  (with_body ? "body::text" : "''") +
                  " FROM (SELECT DISTINCT ON (kind, uuid) * FROM rockface.record "
                  "WHERE tunnel_id = $1 AND ($2::text[] = '{}' OR kind = ANY($2::text[])) "
                  "ORDER BY kind, uuid, revision DESC) latest WHERE NOT deleted",
              {Param::of(tunnel_id), Param::of(list)}, "reading the tunnel's records");
  return records_of(r);
}

namespace {

std::string text_array(const std::vector<std::string>& items) {
  std::string list = "{";
  for (std::size_t i = 0; i < items.size(); ++i) list += (i ? "," : "") + items[i];
  return list + "}";
}

// The uuids a record's body refers to ({"$ref": uuid}, in its row or its
// children's rows).
void referred_uuids(const nlohmann::json& j, std::set<std::string>& out) {
  if (j.is_object()) {
    const auto ref = j.find("$ref");
    if (ref != j.end() && ref->is_string()) out.insert(ref->get<std::string>());
    for (const auto& [k, v] : j.items()) referred_uuids(v, out);
  } else if (j.is_array()) {
    for (const auto& v : j) referred_uuids(v, out);
  }
}

std::vector<ServerRecord> latest_records(Connection& c, const std::string& where,
                                         const std::vector<Param>& params) {
  // DISTINCT ON inside the tunnel's rows, as read_current_records does.
  const Result r = c.query(
      "SELECT kind, uuid::text, visit_uuid::text, project_uuid::text, coalesce(local_id, 0), "
      "project_schema, body::text FROM (SELECT DISTINCT ON (kind, uuid) * FROM rockface.record "
      "WHERE tunnel_id = $1 AND (" +
          where + ") ORDER BY kind, uuid, revision DESC) latest WHERE NOT deleted",
      params, "reading the visits' records");
  return records_of(r);
}

}  // namespace

std::vector<ServerRecord> read_visit_records(Connection& c, std::int64_t tunnel_id,
                                             const std::vector<std::string>& visit_uuids) {
  std::vector<ServerRecord> out =
      latest_records(c, "visit_uuid IS NULL OR visit_uuid = ANY($2::uuid[])",
                     {Param::of(tunnel_id), Param::of(text_array(visit_uuids))});
  std::set<std::string> have;
  for (const ServerRecord& r : out) have.insert(r.uuid);
  // What the records refer to outside them, until nothing is missing (a
  // capture of an earlier visit, then that capture's photographs).
  for (std::vector<ServerRecord> added = out; !added.empty();) {
    std::set<std::string> refs;
    for (const ServerRecord& r : added) referred_uuids(nlohmann::json::parse(r.body), refs);
    std::vector<std::string> missing;
    for (const std::string& u : refs)
      if (!have.count(u)) missing.push_back(u);
    if (missing.empty()) break;
    added = latest_records(c, "uuid = ANY($2::uuid[])",
                           {Param::of(tunnel_id), Param::of(text_array(missing))});
    for (const ServerRecord& r : added) have.insert(r.uuid);
    out.insert(out.end(), added.begin(), added.end());
  }
  return out;
}

std::vector<ServerDriveVisit> read_drive_visits(Connection& c, const ServerTunnel& tunnel,
                                                bool keep_ids) {
  // The three kinds' latest revisions, only the fields the round needs:
  // no record body crosses the connection whole.
  const Result r = c.query(
      "SELECT kind, visit_uuid::text, body->'row'->>'started_at', body->'row'->>'chainage', "
      "body->'row'->>'heading' FROM (SELECT DISTINCT ON (kind, uuid) kind, uuid, visit_uuid, "
      "deleted, body FROM rockface.record WHERE tunnel_id = $1 AND kind IN ('visit', "
      "'visit_placement', 'visit_heading') ORDER BY kind, uuid, revision DESC) latest WHERE NOT "
      "deleted",
      {Param::of(tunnel.id)}, "reading the drive's visits");
  std::map<std::string, ServerDriveVisit> live;
  std::map<std::string, double> chainage;
  std::map<std::string, std::string> heading;
  for (int i = 0; i < r.rows(); ++i) {
    if (r.is_null(i, 1)) continue;
    const std::string kind = r.text(i, 0), visit = r.text(i, 1);
    if (kind == "visit")
      live[visit].started_at = r.is_null(i, 2) ? "" : r.text(i, 2);
    else if (kind == "visit_placement" && !r.is_null(i, 3))
      chainage[visit] = std::strtod(r.text(i, 3).c_str(), nullptr);
    else if (kind == "visit_heading" && !r.is_null(i, 4))
      heading[visit] = r.text(i, 4);
  }
  // The server's order, as a pull inserts the visits.
  std::vector<ServerDriveVisit> out;
  for (const ServerVisit& v : tunnel.visits) {
    const auto it = live.find(v.uuid);
    if (it == live.end()) continue;
    ServerDriveVisit d = it->second;
    d.uuid = v.uuid;
    d.pulled_id = keep_ids ? v.local_id : static_cast<std::int64_t>(out.size() + 1);
    if (const auto ch = chainage.find(v.uuid); ch != chainage.end()) d.chainage = ch->second;
    if (const auto h = heading.find(v.uuid); h != heading.end()) d.heading = h->second;
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace rockface::storage::office
