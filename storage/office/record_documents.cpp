#include "storage/office/record_documents.h"

#include <cmath>
#include <set>

#include "core/common/error.h"
#include "storage/office/record_kinds.h"
#include "storage/office/sha256.h"
#include "storage/office/sqlite_rows.h"

namespace rockface::storage::office {

namespace {

using nlohmann::json;

constexpr std::int64_t kHashPiece = 1 << 20;

// uuid of (table, local id), loaded once per referenced table.
class UuidIndex {
 public:
  explicit UuidIndex(sqlite::Connection& db) : db_(db) {}
  std::string of(const std::string& table, const std::string& to, std::int64_t id) {
    auto& index = tables_[table + "." + to];
    if (index.empty()) {
      const std::string key = to == "id" ? "t.id" : "t." + to;
      const RecordKind* k = find_record_kind(table);
      const std::string uuid_sql = k ? k->uuid_sql : "t.uuid";
      RawStatement st(db_, "SELECT " + key + ", " + uuid_sql + " FROM " + table + " t",
                      "reading the UUIDs of " + table);
      while (st.step()) index[st.int64(0)] = st.text(1);
    }
    const auto it = index.find(id);
    if (it == index.end())
      throw Error(db_.file().string() + ": " + table + " " + std::to_string(id) +
                  " is referred to but missing (run an integrity check)");
    return it->second;
  }

 private:
  sqlite::Connection& db_;
  std::map<std::string, std::map<std::int64_t, std::string>> tables_;
};

struct BlobCache {
  std::map<std::pair<std::string, std::string>, std::pair<std::string, std::int64_t>> known;
  std::vector<std::tuple<std::string, std::string, std::string, std::int64_t>> fresh;
};

std::pair<std::string, std::int64_t> hash_blob(sqlite::Connection& db, const std::string& table,
                                               const std::string& column, std::int64_t rowid) {
  BlobReader reader(db, table, column, rowid);
  Sha256 h;
  std::vector<std::uint8_t> piece;
  for (std::int64_t at = 0; at < reader.size(); at += kHashPiece) {
    piece.resize(static_cast<std::size_t>(std::min(kHashPiece, reader.size() - at)));
    reader.read(at, piece);
    h.add(piece);
  }
  return {h.hex(), reader.size()};
}

// One column value of the current row as JSON (see the header).
json value_of(RawStatement& st, int c) {
  switch (st.type(c)) {
    case SQLITE_NULL:
      return nullptr;
    case SQLITE_INTEGER:
      return st.int64(c);
    case SQLITE_FLOAT: {
      const double v = sqlite3_column_double(st.get(), c);
      if (std::isinf(v)) return json{{"$real", v > 0 ? "inf" : "-inf"}};
      return v;
    }
    case SQLITE_TEXT:
      return st.text(c);
    default: {
      const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(st.get(), c));
      return json{{"$hex", hex_of(p, static_cast<std::size_t>(sqlite3_column_bytes(st.get(), c)))}};
    }
  }
}

struct TableShape {
  std::map<std::string, ForeignKey> refs;  // by column
};

TableShape shape_of(sqlite::Connection& db, const std::string& table) {
  TableShape s;
  for (auto& fk : foreign_keys(db, table)) s.refs[fk.column] = fk;
  return s;
}

// The row's columns from `first` on as JSON, but `skip` ones.
json row_of(RawStatement& st, int first, const TableShape& shape, UuidIndex& uuids,
            const std::set<std::string>& skip, const std::set<std::string>& stored_blobs) {
  json row = json::object();
  for (int c = first; c < st.columns(); ++c) {
    const std::string name = st.name(c);
    if (skip.count(name) || stored_blobs.count(name)) continue;
    const auto ref = shape.refs.find(name);
    if (ref != shape.refs.end() && st.type(c) != SQLITE_NULL)
      row[name] = json{{"$ref", uuids.of(ref->second.table, ref->second.to, st.int64(c))}};
    else
      row[name] = value_of(st, c);
  }
  return row;
}

}  // namespace

ProjectDocuments read_project_documents(sqlite::Connection& db) {
  ProjectDocuments out;
  BlobCache cache;
  {
    sqlite::ReadTransaction snapshot(db);
    {
      RawStatement st(db, "SELECT uuid, name FROM project WHERE id = 1", "reading the project");
      if (!st.step()) throw InputError(db.file().string(), "the project has no project row");
      out.project_uuid = st.text(0);
      out.project_name = st.text(1);
    }
    {
      RawStatement st(db, "SELECT name FROM tunnel WHERE id = 1", "reading the tunnel");
      if (st.step()) out.tunnel_name = st.text(0);
    }
    {
      RawStatement st(db, "SELECT id, uuid, started_at FROM visit ORDER BY id",
                      "reading the visits");
      while (st.step()) out.visits[st.int64(0)] = {st.text(1), st.text(2)};
    }
    {
      RawStatement st(db, "SELECT kind, uuid, sha256, byte_size FROM sync_blob",
                      "reading the blob hashes");
      while (st.step()) cache.known[{st.text(0), st.text(1)}] = {st.text(2), st.int64(3)};
    }
    UuidIndex uuids(db);
    for (const RecordKind& kind : record_kinds()) {
      const TableShape shape = shape_of(db, kind.kind);
      const std::set<std::string> stored(kind.stored_blobs.begin(), kind.stored_blobs.end());
      std::vector<std::pair<std::string, TableShape>> children;
      for (const auto& child : kind.children)
        children.emplace_back(child.table, shape_of(db, child.table));
      RawStatement st(db,
                      "SELECT " + std::string(kind.uuid_sql) + ", " + kind.visit_sql + ", " +
                          kind.local_id_sql + ", t.rowid, t.* FROM " + kind.kind + " t ORDER BY " +
                          kind.local_id_sql,
                      std::string("reading the ") + kind.kind + " records");
      while (st.step()) {
        RecordDocument doc;
        doc.kind = kind.kind;
        doc.uuid = st.text(0);
        if (st.type(1) != SQLITE_NULL) doc.visit_id = st.int64(1);
        doc.local_id = st.int64(2);
        const std::int64_t rowid = st.int64(3);
        if (doc.uuid.empty())
          throw Error(db.file().string() + ": " + kind.kind + " " + std::to_string(doc.local_id) +
                      " has no UUID");
        json body;
        body["row"] = row_of(st, 4, shape, uuids, {"id", "uuid"}, stored);
        for (const char* column : kind.stored_blobs) {
          auto it = cache.known.find({kind.kind, doc.uuid});
          std::pair<std::string, std::int64_t> hash;
          if (it != cache.known.end()) {
            hash = it->second;
          } else {
            hash = hash_blob(db, kind.kind, column, rowid);
            cache.fresh.emplace_back(kind.kind, doc.uuid, hash.first, hash.second);
          }
          body["row"][column] = json{{"$blob", hash.first}, {"size", hash.second}};
          doc.blobs.push_back({hash.first, hash.second, kind.kind, column, rowid});
        }
        json kids = json::object();
        for (std::size_t i = 0; i < kind.children.size(); ++i) {
          const ChildTable& child = kind.children[i];
          RawStatement cs(db,
                          std::string("SELECT * FROM ") + child.table + " WHERE " +
                              child.parent_column + " = ? ORDER BY rowid",
                          std::string("reading the ") + child.table + " rows");
          cs.bind_int64(1, doc.local_id);
          json rows = json::array();
          while (cs.step())
            rows.push_back(row_of(cs, 0, children[i].second, uuids, {child.parent_column}, {}));
          kids[child.table] = std::move(rows);
        }
        body["children"] = std::move(kids);
        doc.body = body.dump();
        doc.content_sha256 = sha256_hex(doc.kind + "\n" + doc.body);
        out.records.push_back(std::move(doc));
      }
    }
  }
  if (!cache.fresh.empty()) {
    sqlite::WriteTransaction tx(db, "remembering the blob hashes");
    RawStatement put(db,
                     "INSERT OR REPLACE INTO sync_blob (kind, uuid, sha256, byte_size) "
                     "VALUES (?, ?, ?, ?)",
                     "remembering the blob hashes");
    for (const auto& [kind, uuid, sha, size] : cache.fresh) {
      put.reset();
      put.bind_text(1, kind);
      put.bind_text(2, uuid);
      put.bind_text(3, sha);
      put.bind_int64(4, size);
      put.step();
    }
    tx.commit();
  }
  return out;
}

}  // namespace rockface::storage::office
