#include "storage/office/sync_push.h"

#include <map>
#include <optional>
#include <set>

#include "core/common/error.h"
#include "storage/office/blob_upload.h"
#include "storage/office/pg_connection.h"
#include "storage/office/record_documents.h"
#include "storage/office/server_schema.h"
#include "storage/office/sqlite_rows.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"

namespace rockface::storage::office {

namespace {

using nlohmann::json;

sqlite::Connection open_project_for_sync(const std::filesystem::path& project) {
  {
    // The store's checks and upgrade (schema 6 gives every record its UUID).
    ProjectStore store = ProjectStore::open(project);
    if (store.read_only())
      throw InputError(project.string(), "cannot sync: " + store.read_only_reason());
  }
  sqlite::Connection db(project, sqlite::Connection::Access::read_write);
  db.exec("PRAGMA busy_timeout = 30000; PRAGMA foreign_keys = ON", "opening the project");
  return db;
}

struct Unit {
  std::optional<std::int64_t> visit_id;  // none: the project's own records
  std::vector<const RecordDocument*> records;
  std::vector<std::pair<std::string, std::string>> tombstones;  // kind, uuid
};

std::string visit_name(const Unit& u) {
  return u.visit_id ? "visit " + std::to_string(*u.visit_id) : "the project's records";
}

std::int64_t server_tunnel(Connection& server, const std::string& tunnel) {
  const Result r = server.query(
      "SELECT id, rockface.is_member(id) OR rockface.is_admin() OR "
      "(SELECT rolsuper FROM pg_roles WHERE rolname = current_user) "
      "FROM rockface.tunnel WHERE name = $1",
      {Param::of(tunnel)}, "finding the tunnel");
  if (r.rows() == 0 || r.text(0, 1) != "t")
    throw InputError("tunnel " + tunnel,
                     "not on " + server.label() + ", or role " + server.current_user() +
                         " may not add visits to it (an administrator runs `rockface server "
                         "add-tablet`)");
  return r.int64(0, 0);
}

std::int64_t sync_target_id(sqlite::Connection& db, const std::string& server_id,
                            const std::string& label, const std::string& tunnel) {
  sqlite::WriteTransaction tx(db, "recording the sync's server");
  RawStatement put(db,
                   "INSERT INTO sync_target (server_id, server_label, tunnel) VALUES (?, ?, ?) "
                   "ON CONFLICT (server_id) DO UPDATE SET server_label = excluded.server_label, "
                   "tunnel = excluded.tunnel",
                   "recording the sync's server");
  put.bind_text(1, server_id);
  put.bind_text(2, label);
  put.bind_text(3, tunnel);
  put.step();
  RawStatement get(db, "SELECT id FROM sync_target WHERE server_id = ?", "recording the sync");
  get.bind_text(1, server_id);
  get.step();
  const std::int64_t id = get.int64(0);
  tx.commit();
  return id;
}

void record_outcome(sqlite::Connection& db, std::int64_t target, std::int64_t run,
                    const std::string& outcome, const SyncResult& r, bool finished) {
  sqlite::WriteTransaction tx(db, "recording the sync's outcome");
  RawStatement t(db,
                 finished
                     ? "UPDATE sync_target SET last_sync_at = ?, last_outcome = ? WHERE id = ?"
                     : "UPDATE sync_target SET last_outcome = ? WHERE id = ? AND ? IS NOT NULL",
                 "recording the sync's outcome");
  const std::string now = utc_now_iso8601();
  if (finished) {
    t.bind_text(1, now);
    t.bind_text(2, outcome);
    t.bind_int64(3, target);
  } else {
    t.bind_text(1, outcome);
    t.bind_int64(2, target);
    t.bind_text(3, now);
  }
  t.step();
  RawStatement s(db,
                 "UPDATE sync_run SET finished_at = ?, outcome = ?, records_sent = ?, "
                 "blobs_sent = ?, bytes_sent = ? WHERE id = ?",
                 "recording the sync's outcome");
  s.bind_text(1, now);
  s.bind_text(2, outcome);
  s.bind_int64(3, r.records_sent);
  s.bind_int64(4, r.blobs_sent);
  s.bind_int64(5, r.blob_bytes_sent + r.record_bytes_sent);
  s.bind_int64(6, run);
  s.step();
  tx.commit();
}

std::map<std::pair<std::string, std::string>, std::string> synced_records(sqlite::Connection& db,
                                                                          std::int64_t target) {
  std::map<std::pair<std::string, std::string>, std::string> out;
  RawStatement st(db, "SELECT kind, uuid, content_sha256 FROM sync_record WHERE target_id = ?",
                  "reading what was synced");
  st.bind_int64(1, target);
  while (st.step()) out[{st.text(0), st.text(1)}] = st.text(2);
  return out;
}

// The units in the order they go up, with what changed since the last sync.
std::vector<Unit> dirty_units(
    const ProjectDocuments& docs,
    const std::map<std::pair<std::string, std::string>, std::string>& known) {
  std::map<std::optional<std::int64_t>, Unit> units;
  units[std::nullopt].visit_id = std::nullopt;
  std::set<std::pair<std::string, std::string>> present;
  std::set<std::optional<std::int64_t>> dirty;
  for (const RecordDocument& d : docs.records) {
    Unit& u = units[d.visit_id];
    u.visit_id = d.visit_id;
    u.records.push_back(&d);
    present.insert({d.kind, d.uuid});
    const auto it = known.find({d.kind, d.uuid});
    if (it == known.end() || it->second != d.content_sha256) dirty.insert(d.visit_id);
  }
  for (const auto& [key, sha] : known)
    if (!present.count(key) && sha != "deleted") {
      units[std::nullopt].tombstones.push_back(key);
      dirty.insert(std::nullopt);
    }
  std::vector<Unit> out;
  for (auto& [id, unit] : units)
    if (dirty.count(id)) out.push_back(std::move(unit));
  return out;
}

void send_unit(Connection& server, sqlite::Connection& db, const ProjectDocuments& docs,
               std::int64_t tunnel_id, std::int64_t target, const Unit& unit, SyncResult& result,
               Progress& progress, double fraction) {
  const std::string doing = "sending " + visit_name(unit);
  json batch = json::array();
  std::string text = "[";
  auto add = [&](const std::string& kind, const std::string& uuid,
                 std::optional<std::int64_t> local, std::optional<std::int64_t> visit,
                 const std::string& sha, const std::string* body) {
    json head{
        {"kind", kind}, {"uuid", uuid}, {"content_sha256", sha}, {"deleted", body == nullptr}};
    head["local_id"] = local ? json(*local) : json(nullptr);
    head["visit_uuid"] = visit ? json(docs.visits.at(*visit).uuid) : json(nullptr);
    std::string h = head.dump();
    h.pop_back();  // '}'
    if (text.size() > 1) text += ",";
    text += h + ",\"body\":" + (body ? *body : std::string("null")) + "}";
  };
  for (const RecordDocument* d : unit.records)
    add(d->kind, d->uuid, d->local_id, d->visit_id, d->content_sha256, &d->body);
  for (const auto& [kind, uuid] : unit.tombstones)
    add(kind, uuid, std::nullopt, std::nullopt, "deleted", nullptr);
  text += "]";

  Transaction tx(server, doing);
  server.query(
      "INSERT INTO rockface.project (uuid, tunnel_id, name) VALUES ($1::uuid, $2, $3) "
      "ON CONFLICT (uuid) DO NOTHING",
      {Param::of(docs.project_uuid), Param::of(tunnel_id), Param::of(docs.project_name)}, doing);
  if (unit.visit_id) {
    const auto& v = docs.visits.at(*unit.visit_id);
    server.query(
        "INSERT INTO rockface.visit (uuid, tunnel_id, project_uuid, local_id, started_at) "
        "VALUES ($1::uuid, $2, $3::uuid, $4, $5) ON CONFLICT (uuid) DO NOTHING",
        {Param::of(v.uuid), Param::of(tunnel_id), Param::of(docs.project_uuid),
         Param::of(*unit.visit_id), Param::of(v.started_at)},
        doing);
  }
  const Result sent = server.query(
      "WITH incoming AS (SELECT * FROM jsonb_to_recordset($1::jsonb) AS x(kind text, uuid uuid, "
      "  local_id bigint, visit_uuid uuid, content_sha256 text, deleted boolean, body jsonb)), "
      "current AS (SELECT DISTINCT ON (r.kind, r.uuid) r.kind, r.uuid, r.revision, "
      "  r.content_sha256 FROM rockface.record r JOIN incoming i USING (kind, uuid) "
      "  ORDER BY r.kind, r.uuid, r.revision DESC) "
      "INSERT INTO rockface.record (kind, uuid, revision, tunnel_id, project_uuid, visit_uuid, "
      "  local_id, project_schema, content_sha256, deleted, body) "
      "SELECT i.kind, i.uuid, coalesce(c.revision, 0) + 1, $2, $3::uuid, i.visit_uuid, "
      "  i.local_id, $4, i.content_sha256, i.deleted, i.body "
      "FROM incoming i LEFT JOIN current c USING (kind, uuid) "
      "WHERE c.content_sha256 IS DISTINCT FROM i.content_sha256 "
      "RETURNING kind, uuid, revision",
      {Param::of(text), Param::of(tunnel_id), Param::of(docs.project_uuid),
       Param::of(std::int64_t{schema::kCurrentVersion})},
      doing);
  tx.commit();
  result.records_sent += sent.rows();
  result.record_bytes_sent += static_cast<std::int64_t>(text.size());
  ++result.units_sent;

  // A kill (or cancel) here leaves the unit on the server but not in the
  // tablet's record: the next sync sends it again, and the server, finding
  // the same content as the latest revision, stores nothing.
  progress.step("recording what was synced", fraction);
  std::map<std::pair<std::string, std::string>, std::int64_t> revisions;
  for (int i = 0; i < sent.rows(); ++i)
    revisions[{sent.text(i, 0), sent.text(i, 1)}] = sent.int64(i, 2);
  sqlite::WriteTransaction local(db, "recording what was synced");
  RawStatement put(db,
                   "INSERT INTO sync_record (target_id, kind, uuid, content_sha256, revision, "
                   "synced_at) VALUES (?, ?, ?, ?, ?, ?) ON CONFLICT (target_id, kind, uuid) DO "
                   "UPDATE SET content_sha256 = excluded.content_sha256, synced_at = "
                   "excluded.synced_at, revision = CASE WHEN excluded.revision > 0 THEN "
                   "excluded.revision ELSE sync_record.revision END",
                   "recording what was synced");
  const std::string now = utc_now_iso8601();
  auto remember = [&](const std::string& kind, const std::string& uuid, const std::string& sha) {
    put.reset();
    put.bind_int64(1, target);
    put.bind_text(2, kind);
    put.bind_text(3, uuid);
    put.bind_text(4, sha);
    const auto it = revisions.find({kind, uuid});
    put.bind_int64(5, it == revisions.end() ? 0 : it->second);
    put.bind_text(6, now);
    put.step();
  };
  for (const RecordDocument* d : unit.records) remember(d->kind, d->uuid, d->content_sha256);
  for (const auto& [kind, uuid] : unit.tombstones) remember(kind, uuid, "deleted");
  local.commit();
}

}  // namespace

SyncStatus sync_status(const std::filesystem::path& project) {
  SyncStatus status;
  sqlite::Connection db = open_project_for_sync(project);
  std::int64_t target = 0;
  {
    RawStatement st(db,
                    "SELECT id, server_label, tunnel, coalesce(last_sync_at, ''), last_outcome "
                    "FROM sync_target ORDER BY coalesce(last_sync_at, '') DESC, id DESC LIMIT 1",
                    "reading the last sync");
    if (st.step()) {
      status.ever_synced = true;
      target = st.int64(0);
      status.server_label = st.text(1);
      status.tunnel = st.text(2);
      status.last_sync_at = st.text(3);
      status.last_outcome = st.text(4);
    }
  }
  const ProjectDocuments docs = read_project_documents(db);
  const auto known = status.ever_synced
                         ? synced_records(db, target)
                         : std::map<std::pair<std::string, std::string>, std::string>{};
  std::set<std::optional<std::int64_t>> visits;
  std::set<std::pair<std::string, std::string>> present;
  for (const RecordDocument& d : docs.records) {
    present.insert({d.kind, d.uuid});
    const auto it = known.find({d.kind, d.uuid});
    if (it == known.end() || it->second != d.content_sha256) {
      ++status.records_waiting;
      if (d.visit_id) visits.insert(d.visit_id);
    }
  }
  // A record gone from the project since the last sync waits too: its
  // deletion goes up as a revision (dirty_units' tombstones).
  for (const auto& [key, sha] : known)
    if (!present.count(key) && sha != "deleted") ++status.records_waiting;
  status.visits_waiting = static_cast<int>(visits.size());
  return status;
}

SyncResult sync_project(const std::filesystem::path& project, const std::string& conninfo,
                        const SyncOptions& options, Progress& progress) {
  if (options.chunk_bytes < 1024 || options.chunk_bytes > (64 << 20))
    throw InputError("chunk size", "between 1 KiB and 64 MiB");
  sqlite::Connection db = open_project_for_sync(project);
  SyncResult result;
  progress.step("connecting to the server", 0);
  Connection server(conninfo, options.connect_timeout_s);
  result.server_label = server.label();
  require_compatible_server(server);
  const std::string sid = server_id(server);
  const ProjectDocuments docs = read_project_documents(db);
  result.tunnel = options.tunnel.empty() ? docs.tunnel_name : options.tunnel;
  if (result.tunnel.empty())
    throw InputError(project.string(),
                     "the project has no tunnel: name the server's tunnel with --tunnel");
  progress.step("connecting to the server", 0);
  const std::int64_t tunnel_id = server_tunnel(server, result.tunnel);
  const std::int64_t target = sync_target_id(db, sid, server.label(), result.tunnel);
  std::int64_t run = 0;
  const std::string started = utc_now_iso8601();
  {
    sqlite::WriteTransaction tx(db, "recording the sync");
    RawStatement st(db, "INSERT INTO sync_run (target_id, started_at) VALUES (?, ?)",
                    "recording the sync");
    st.bind_int64(1, target);
    st.bind_text(2, started);
    st.step();
    run = db.last_insert_id();
    tx.commit();
  }
  try {
    const std::vector<Unit> units = dirty_units(docs, synced_records(db, target));
    result.units_total = static_cast<int>(units.size());
    // Blobs first: a record may only refer to a complete blob.
    std::vector<BlobSource> blobs;
    std::set<std::string> seen;
    for (const Unit& u : units)
      for (const RecordDocument* d : u.records)
        for (const BlobSource& b : d->blobs)
          if (seen.insert(b.sha256).second) blobs.push_back(b);
    BlobUploadStats stats;
    for (std::size_t i = 0; i < blobs.size(); ++i)
      upload_blob(server, db, blobs[i], options.chunk_bytes, progress,
                  0.5 * static_cast<double>(i) / static_cast<double>(blobs.size()), stats);
    result.blobs_sent = stats.sent;
    result.blobs_already_there = stats.already_there;
    result.blob_bytes_sent = stats.bytes;
    for (std::size_t i = 0; i < units.size(); ++i) {
      const double fraction =
          0.5 + 0.5 * static_cast<double>(i) / static_cast<double>(units.size());
      progress.step("sending the records", fraction);
      send_unit(server, db, docs, tunnel_id, target, units[i], result, progress, fraction);
    }
    progress.step("sending the records", 1);
    server.query(
        "INSERT INTO rockface.sync_log (project_uuid, started_at, records, blobs, bytes, client) "
        "VALUES ($1::uuid, $2::timestamptz, $3, $4, $5, $6)",
        {Param::of(docs.project_uuid), Param::of(started),
         Param::of(std::int64_t{result.records_sent}), Param::of(std::int64_t{result.blobs_sent}),
         Param::of(result.blob_bytes_sent + result.record_bytes_sent),
         Param::of(std::string("rockface 0.1, project schema ") +
                   std::to_string(schema::kCurrentVersion))},
        "logging the sync");
    record_outcome(db, target, run, "complete", result, true);
  } catch (const Cancelled&) {
    record_outcome(db, target, run, "cancelled (the next sync resumes it)", result, false);
    throw;
  } catch (const std::exception& e) {
    try {
      record_outcome(db, target, run, std::string("interrupted: ") + e.what(), result, false);
    } catch (...) {
    }
    throw;
  }
  return result;
}

}  // namespace rockface::storage::office
