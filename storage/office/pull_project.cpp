#include "storage/office/pull_project.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/office/record_kinds.h"
#include "storage/office/server_records.h"
#include "storage/office/server_schema.h"
#include "storage/office/sha256.h"
#include "storage/office/sqlite_rows.h"
#include "storage/project/blob_parts.h"
#include "storage/project/project_store.h"

namespace rockface::storage::office {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class ProjectWriter {
 public:
  // `visit_ids`: the id each visit takes (by uuid), when not its own.
  ProjectWriter(sqlite::Connection& db, BlobSpool& blobs, bool keep_ids, const PullOptions& options,
                PullResult& result, Progress& progress,
                std::map<std::string, std::int64_t> visit_ids = {})
      : db_(db),
        blobs_(blobs),
        keep_ids_(keep_ids),
        options_(options),
        result_(result),
        progress_(progress),
        visit_ids_(std::move(visit_ids)) {}

  // Inserts one record (and its children); returns its row id.
  void insert(const ServerRecord& rec) {
    const std::string where = rec.kind + " " + rec.uuid;
    const json body = json::parse(rec.body);
    const json& row = body.at("row");
    if (rec.kind == "camera_body") {
      // Two tablets with the same camera: one body, as the store keeps it.
      RawStatement same(db_,
                        "SELECT id FROM camera_body WHERE make = ? AND model = ? AND serial = ?",
                        "finding a camera body");
      same.bind_text(1, row.at("make").get<std::string>());
      same.bind_text(2, row.at("model").get<std::string>());
      same.bind_text(3, row.at("serial").get<std::string>());
      if (same.step()) {
        ids_[{rec.kind, rec.uuid}] = same.int64(0);
        return;
      }
    }
    if (rec.kind == "image") {
      // Identical photographs from several tablets are stored once, as the
      // project store does.
      const std::string sha = row.at("bytes").at("$blob").get<std::string>();
      const auto same = images_.find(sha + "/" + row.at("format").get<std::string>());
      if (same != images_.end()) {
        ids_[{rec.kind, rec.uuid}] = same->second;
        return;
      }
    }
    // The record keeps its UUID (the body holds it as its key, not a column).
    json with_uuid = row;
    if (has_column(rec.kind, "uuid")) with_uuid["uuid"] = rec.uuid;
    std::int64_t keep_id = keep_ids_ ? rec.local_id : 0;
    if (rec.kind == "visit")
      if (const auto it = visit_ids_.find(rec.uuid); it != visit_ids_.end()) keep_id = it->second;
    const std::int64_t rowid = insert_row(rec.kind, with_uuid, where, keep_id);
    ids_[{rec.kind, rec.uuid}] = key_of(rec.kind, "id", rowid);
    if (rec.kind == "visit_placement")
      ids_[{rec.kind, rec.uuid}] = key_of(rec.kind, "visit_id", rowid);
    if (rec.kind == "image")
      images_[row.at("bytes").at("$blob").get<std::string>() + "/" +
              row.at("format").get<std::string>()] = rowid;
    const RecordKind* kind = find_record_kind(rec.kind);
    if (kind && body.contains("children")) {
      for (const ChildTable& child : kind->children) {
        const auto it = body["children"].find(child.table);
        if (it == body["children"].end()) continue;
        std::string to = "id";
        for (const auto& fk : fks(child.table))
          if (fk.column == child.parent_column) to = fk.to;
        const std::int64_t parent = key_of(rec.kind, to, rowid);
        for (json r : *it) {
          r[child.parent_column] = parent;
          insert_row(child.table, r, where + " " + child.table, 0);
        }
      }
    }
  }

 private:
  std::int64_t key_of(const std::string& table, const std::string& column, std::int64_t rowid) {
    if (column == "id" && has_column(table, "id")) return rowid;
    if (!has_column(table, column)) return rowid;
    RawStatement st(db_, "SELECT " + column + " FROM " + table + " WHERE rowid = ?",
                    "reading back " + table);
    st.bind_int64(1, rowid);
    st.step();
    return st.int64(0);
  }

  const std::vector<ForeignKey>& fks(const std::string& table) {
    auto it = fks_.find(table);
    if (it == fks_.end()) it = fks_.emplace(table, foreign_keys(db_, table)).first;
    return it->second;
  }
  bool has_column(const std::string& table, const std::string& column) {
    auto it = columns_.find(table);
    if (it == columns_.end()) {
      const auto names = column_names(db_, table);
      it = columns_.emplace(table, std::set<std::string>(names.begin(), names.end())).first;
    }
    return it->second.count(column) > 0;
  }

  std::int64_t insert_row(const std::string& table, const json& row, const std::string& where,
                          std::int64_t keep_id) {
    std::vector<std::string> names;
    std::vector<const json*> values;
    std::vector<std::pair<std::string, json>> blobs;
    for (auto it = row.begin(); it != row.end(); ++it) {
      if (!has_column(table, it.key()))
        throw InputError(where, "has column " + it.key() + " that this rockface's " + table +
                                    " table does not know: update rockface");
      names.push_back(it.key());
      values.push_back(&it.value());
    }
    std::string sql = "INSERT INTO " + table + " (";
    std::string marks;
    const bool with_id = keep_id > 0 && has_column(table, "id");
    if (with_id) {
      sql += "id, ";
      marks += "?, ";
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      sql += (i ? ", " : "") + names[i];
      marks += (i ? ", ?" : "?");
    }
    sql += ") VALUES (" + marks + ")";
    // Prepared once per table and column list, not per row: parsing each
    // INSERT (and coding the table's triggers into it) was most of a
    // visit's copy (docs/accuracy-cost.md, issue 46's profile).
    auto prepared = inserts_.find(sql);
    if (prepared == inserts_.end())
      prepared =
          inserts_.emplace(sql, std::make_unique<RawStatement>(db_, sql, "writing " + where)).first;
    RawStatement& st = *prepared->second;
    st.reset("writing " + where);
    if (with_id) st.bind_int64(1, keep_id);
    const int first = with_id ? 2 : 1;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const int at = static_cast<int>(i) + first;
      const json& v = *values[i];
      if (v.is_null()) {
        st.bind_null(at);
      } else if (v.is_number_integer()) {
        st.bind_int64(at, v.get<std::int64_t>());
      } else if (v.is_number_float()) {
        sqlite3_bind_double(st.get(), at, v.get<double>());
      } else if (v.is_string()) {
        st.bind_text(at, v.get<std::string>());
      } else if (v.is_object() && v.contains("$ref")) {
        st.bind_int64(at, resolve(table, names[i], v["$ref"].get<std::string>(), where));
      } else if (v.is_object() && v.contains("$blob")) {
        // A column stored in parts (a model's mesh) stays empty: its bytes
        // go into its parts table as the tablet's own save writes them.
        const bool in_parts = parts::parts_table_of(table, names[i]) != nullptr;
        // A photograph left on the server: an empty blob (the column is
        // NOT NULL), its size kept in the row's byte_size.
        const bool photograph_left = table == "image" && !options_.photographs;
        const bool mesh_left = in_parts && !options_.meshes;
        sqlite3_bind_zeroblob64(
            st.get(), at, in_parts || photograph_left ? 0 : v.at("size").get<std::uint64_t>());
        if (photograph_left)
          ++result_.photographs_left;
        else if (mesh_left)
          ++result_.meshes_left;
        else
          blobs.emplace_back(names[i], v);
      } else if (v.is_object() && v.contains("$hex")) {
        const auto bytes = bytes_of_hex(v["$hex"].get<std::string>(), where + "." + names[i]);
        sqlite3_bind_blob(st.get(), at, bytes.data(), static_cast<int>(bytes.size()),
                          SQLITE_TRANSIENT);
      } else if (v.is_object() && v.contains("$real")) {
        sqlite3_bind_double(st.get(), at, v["$real"] == "inf" ? HUGE_VAL : -HUGE_VAL);
      } else {
        throw InputError(where + "." + names[i], "a value this rockface cannot store");
      }
    }
    st.step();
    const std::int64_t rowid = sqlite3_last_insert_rowid(db_.handle());
    for (const auto& [column, ref] : blobs)
      copy_blob(table, column, rowid, ref["$blob"].get<std::string>(),
                ref["size"].get<std::int64_t>());
    return rowid;
  }

  std::int64_t resolve(const std::string& table, const std::string& column, const std::string& uuid,
                       const std::string& where) {
    for (const auto& fk : fks(table)) {
      if (fk.column != column) continue;
      const auto it = ids_.find({fk.table, uuid});
      if (it == ids_.end())
        throw InputError(where, column + " refers to " + fk.table + " " + uuid +
                                    ", which is not among the tunnel's records on the server");
      return it->second;
    }
    throw InputError(where,
                     column + " is a reference this rockface's " + table + " table does not have");
  }

  // Writes one blob, read from the server and checked by read_pull, into
  // the row (or its parts table).
  void copy_blob(const std::string& table, const std::string& column, std::int64_t rowid,
                 const std::string& sha, std::int64_t size) {
    progress_.step("building the project", 0.5);
    std::optional<BlobWriter> writer;
    std::optional<parts::PartWriter> in_parts;
    if (const auto* table_of_parts = parts::parts_table_of(table, column))
      in_parts.emplace(db_, *table_of_parts, rowid);
    else
      writer.emplace(db_, table, column, rowid);
    std::int64_t at = 0;
    blobs_.copy(sha, [&](const std::uint8_t* bytes, std::size_t n) {
      if (in_parts)
        in_parts->append(bytes, n);
      else
        writer->write(at, bytes, n);
      at += static_cast<std::int64_t>(n);
    });
    if (in_parts) in_parts->finish();
    ++result_.blobs;
    result_.blob_bytes += size;
  }

  sqlite::Connection& db_;
  BlobSpool& blobs_;
  bool keep_ids_;
  PullOptions options_;
  PullResult& result_;
  Progress& progress_;
  std::map<std::string, std::int64_t> visit_ids_;
  std::map<std::pair<std::string, std::string>, std::int64_t> ids_;  // (kind, uuid) -> key
  std::map<std::string, std::int64_t> images_;                       // sha/format -> row
  std::map<std::string, std::vector<ForeignKey>> fks_;
  std::map<std::string, std::set<std::string>> columns_;
  std::map<std::string, std::unique_ptr<RawStatement>> inserts_;  // by their SQL
};

// The project row every tablet's project of the tunnel must agree on: its
// datum (a merged project holds coordinates relative to one datum).
const ServerRecord& base_project(const std::vector<ServerRecord>& records,
                                 const ServerTunnel& tunnel) {
  const ServerRecord* base = nullptr;
  json datum;
  for (const std::string& uuid : tunnel.projects)
    for (const ServerRecord& r : records) {
      if (r.kind != "project" || r.project_uuid != uuid) continue;
      const json row = json::parse(r.body).at("row");
      const json d = {row.at("datum_x"), row.at("datum_y"), row.at("datum_z"), row.at("datum_crs")};
      if (!base) {
        base = &r;
        datum = d;
      } else if (d != datum) {
        throw InputError("tunnel " + tunnel.name, "its projects have different datums (" +
                                                      datum.dump() + " and " + d.dump() +
                                                      " of project " + uuid +
                                                      "): they cannot be merged into one project");
      }
    }
  if (!base) throw InputError("tunnel " + tunnel.name, "no project has synced to it yet");
  return *base;
}

// A tunnel record's design (alignment, profile, drive, tolerance) without
// what differs between two tablets that hold the same design: local ids,
// when it was entered and the names of the files it came from.
json tunnel_design(const std::string& body) {
  json doc = json::parse(body);
  json& row = doc["row"];
  for (const char* k : {"id", "created_at", "alignment_source", "profile_source"}) row.erase(k);
  if (doc.contains("children"))
    for (auto& [table, rows] : doc["children"].items())
      for (json& child : rows) {
        child.erase("id");
        child.erase("tunnel_id");
      }
  return doc;
}

std::string project_name(const std::vector<ServerRecord>& records, const std::string& uuid) {
  for (const ServerRecord& r : records)
    if (r.kind == "project" && r.project_uuid == uuid) {
      const json row = json::parse(r.body).at("row");
      if (row.contains("name") && row["name"].is_string()) return row["name"];
    }
  return uuid;
}

// The pulled project holds one tunnel: the base project's when it has one,
// else the last synced project's (the order the records go in). Says so
// when the tablets carry different designs.
std::vector<std::string> tunnel_disagreements(const std::vector<ServerRecord>& records,
                                              const ServerTunnel& tunnel,
                                              const std::string& base_project_uuid) {
  std::vector<const ServerRecord*> tunnels;
  for (const std::string& uuid : tunnel.projects)
    for (const ServerRecord& r : records)
      if (r.kind == "tunnel" && r.project_uuid == uuid) tunnels.push_back(&r);
  if (tunnels.size() < 2) return {};
  const ServerRecord* kept = tunnels.back();
  for (const ServerRecord* r : tunnels)
    if (r->project_uuid == base_project_uuid) kept = r;
  const json design = tunnel_design(kept->body);
  std::vector<std::string> differ;
  for (const ServerRecord* r : tunnels)
    if (tunnel_design(r->body) != design)
      differ.push_back("'" + project_name(records, r->project_uuid) + "'");
  if (differ.empty()) return {};
  std::string names = differ.front();
  for (std::size_t i = 1; i < differ.size(); ++i) names += ", " + differ[i];
  return {"tunnel " + tunnel.name +
          ": the tablets' projects carry different designs of it (alignment, profile, drive or "
          "underbreak tolerance); the pulled project holds the one of project '" +
          project_name(records, kept->project_uuid) + "', and project" +
          (differ.size() > 1 ? "s " : " ") + names +
          " differ: check which design is current before reading over- and underbreak"};
}

// Reads into the spool every blob the project will hold: what the options
// leave on the server is not read (photograph_left / mesh_left in
// insert_row).
void spool_blobs(Connection& server, const std::vector<ServerRecord>& records,
                 const PullOptions& options, BlobSpool& spool, Progress& progress) {
  auto row_blobs = [&](const std::string& table, const json& row, const std::string& where) {
    for (auto it = row.begin(); it != row.end(); ++it) {
      const json& v = it.value();
      if (!v.is_object() || !v.contains("$blob")) continue;
      const bool in_parts = parts::parts_table_of(table, it.key()) != nullptr;
      if (table == "image" && !options.photographs) continue;
      if (in_parts && !options.meshes) continue;
      const std::string sha = v["$blob"].get<std::string>();
      spool.fetch(server, sha, v.at("size").get<std::int64_t>(),
                  where + " " + it.key() + " (blob " + sha + ")", progress);
    }
  };
  for (const ServerRecord& rec : records) {
    if (rec.kind == "project") continue;
    const std::string where = rec.kind + " " + rec.uuid;
    const json body = json::parse(rec.body);
    row_blobs(rec.kind, body.at("row"), where);
    const RecordKind* kind = find_record_kind(rec.kind);
    if (!kind || !body.contains("children")) continue;
    for (const ChildTable& child : kind->children) {
      const auto it = body["children"].find(child.table);
      if (it == body["children"].end()) continue;
      for (const json& r : *it) row_blobs(child.table, r, where + " " + child.table);
    }
  }
}

}  // namespace

PullResult pull_tunnel(const std::string& conninfo, const std::string& tunnel_name,
                       const fs::path& out, Progress& progress, int connect_timeout_s) {
  if (fs::exists(out)) throw InputError(out.string(), "exists already: pull makes a new project");
  progress.step("connecting to the server", 0);
  Connection server(conninfo, connect_timeout_s);
  return pull_tunnel(server, tunnel_name, out, progress);
}

PullResult pull_tunnel(Connection& server, const std::string& tunnel_name, const fs::path& out,
                       Progress& progress, const PullOptions& options) {
  PullRead read = read_pull(server, tunnel_name, out, progress, options);
  return build_pulled_project(read, progress);
}

PullRead read_pull(Connection& server, const std::string& tunnel_name, const fs::path& out,
                   Progress& progress, const PullOptions& options) {
  if (fs::exists(out)) throw InputError(out.string(), "exists already: pull makes a new project");
  PullRead read;
  read.out = out;
  read.options = options;
  PullResult& result = read.result;
  result.server_label = server.label();
  require_compatible_server(server);
  // One snapshot of the server for the whole read.
  server.exec("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY", "reading the tunnel");
  try {
    read.tunnel = read_server_tunnel(server, tunnel_name);
    const ServerTunnel& tunnel = read.tunnel;
    std::vector<ServerRecord>& records = read.records;
    records = options.visits.empty() ? read_current_records(server, tunnel.id, {})
                                     : read_visit_records(server, tunnel.id, options.visits);
    read.base = base_project(records, tunnel);  // a copy: records are sorted below
    result.projects = static_cast<int>(tunnel.projects.size());
    result.visits = static_cast<int>(tunnel.visits.size());
    read.keep_ids = tunnel.projects.size() == 1;
    if (!options.visits.empty())
      read.drive_visits = read_drive_visits(server, tunnel, read.keep_ids);
    result.warnings = tunnel_disagreements(records, tunnel, read.base.project_uuid);

    // The order records go in: kinds in dependency order; visits in the
    // server's order; the rest by project, then their local order.
    std::map<std::string, int> visit_rank, project_rank, kind_rank;
    for (std::size_t i = 0; i < tunnel.visits.size(); ++i)
      visit_rank[tunnel.visits[i].uuid] = static_cast<int>(i);
    for (std::size_t i = 0; i < tunnel.projects.size(); ++i)
      project_rank[tunnel.projects[i]] = static_cast<int>(i);
    for (std::size_t i = 0; i < record_kinds().size(); ++i)
      kind_rank[record_kinds()[i].kind] = static_cast<int>(i);
    for (const ServerRecord& r : records)
      if (!kind_rank.count(r.kind))
        throw InputError(r.kind + " " + r.uuid, "a kind of record this rockface does not know");
    auto key = [&](const ServerRecord& r) {
      const int k = kind_rank[r.kind];
      if (r.kind == "visit") return std::tuple(k, visit_rank[r.uuid], 0, r.local_id);
      return std::tuple(k, 0, project_rank[r.project_uuid], r.local_id);
    };
    std::sort(records.begin(), records.end(),
              [&](const ServerRecord& a, const ServerRecord& b) { return key(a) < key(b); });

    read.blobs = std::make_unique<BlobSpool>(fs::path(out.string() + ".blobs.partial"));
    spool_blobs(server, records, options, *read.blobs, progress);
  } catch (...) {
    // The snapshot's transaction ends with the read, whatever happened.
    try {
      server.exec("ROLLBACK", "ending a failed pull");
    } catch (...) {
    }
    throw;
  }
  server.exec("COMMIT", "reading the tunnel");
  return read;
}

PullResult build_pulled_project(PullRead& read, Progress& progress) {
  const fs::path& out = read.out;
  const std::vector<ServerRecord>& records = read.records;
  const ServerRecord& base = read.base;
  PullResult& result = read.result;
  if (fs::exists(out)) throw InputError(out.string(), "exists already: pull makes a new project");
  const fs::path partial = fs::path(out.string() + ".partial");
  fs::remove(partial);
  fs::remove(fs::path(partial.string() + "-wal"));
  fs::remove(fs::path(partial.string() + "-shm"));
  try {
    {
      ProjectInfo info;
      info.name = "pulled";
      ProjectStore::create(partial, info);
    }
    {
      sqlite::Connection db(partial, sqlite::Connection::Access::read_write);
      db.exec("PRAGMA foreign_keys = ON", "building the pulled project");
      sqlite::WriteTransaction tx(db, "building the pulled project");
      db.exec("DELETE FROM action_log", "building the pulled project");
      // The project row as the first project synced it.
      json row = json::parse(base.body).at("row");
      row["uuid"] = base.uuid;
      for (auto it = row.begin(); it != row.end(); ++it) {
        RawStatement st(db, "UPDATE project SET " + it.key() + " = ? WHERE id = 1",
                        "writing the project row");
        if (it->is_string())
          st.bind_text(1, it->get<std::string>());
        else if (it->is_number_integer())
          st.bind_int64(1, it->get<std::int64_t>());
        else if (it->is_number_float())
          sqlite3_bind_double(st.get(), 1, it->get<double>());
        else
          st.bind_null(1);
        st.step();
      }
      // A copy of some visits numbers them as a pull of the whole tunnel
      // does: a round's "face of visit N" reads the same in both.
      std::map<std::string, std::int64_t> visit_ids;
      for (const ServerDriveVisit& v : read.drive_visits) visit_ids[v.uuid] = v.pulled_id;
      ProjectWriter writer(db, *read.blobs, read.keep_ids, read.options, result, progress,
                           std::move(visit_ids));
      for (std::size_t i = 0; i < records.size(); ++i) {
        const ServerRecord& r = records[i];
        if (r.kind == "project") continue;
        // One tablet's tunnel record is the tunnel (the latest synced wins
        // when several tablets carry it).
        if (r.kind == "tunnel" && r.project_uuid != base.project_uuid) {
          bool base_has = false;
          for (const ServerRecord& o : records)
            base_has |= o.kind == "tunnel" && o.project_uuid == base.project_uuid;
          if (base_has) continue;
          db.exec("DELETE FROM tunnel", "writing the tunnel");
        }
        progress.step("building the project",
                      0.5 + 0.5 * static_cast<double>(i) / static_cast<double>(records.size()));
        writer.insert(r);
        ++result.records;
      }
      tx.commit();
    }
    // The pulled file passes the store's full check before it takes its name.
    {
      OpenOptions check;
      check.check = OpenOptions::Check::full;
      ProjectStore store = ProjectStore::open(partial, check);
      store.checkpoint();
    }
    // link() refuses a name taken since the check above (rename would
    // replace that file): a pull never overwrites a project.
    if (::link(partial.c_str(), out.c_str()) != 0) {
      const int err = errno;
      throw InputError(out.string(), std::string("the pulled project cannot take this name: ") +
                                         std::strerror(err));
    }
    std::error_code ec;
    fs::remove(partial, ec);
  } catch (...) {
    std::error_code ec;
    fs::remove(partial, ec);
    fs::remove(fs::path(partial.string() + "-wal"), ec);
    fs::remove(fs::path(partial.string() + "-shm"), ec);
    throw;
  }
  return result;
}

}  // namespace rockface::storage::office
