#pragma once
// A project's records as the office server keeps them: each row (with the
// rows of its child tables) as one JSON document whose references to other
// records are their UUIDs, whose photographs and meshes are their SHA-256,
// and whose other values are exactly the stored ones (integers, doubles in
// shortest round-trip form, text, small blobs as hex), so that a project
// rebuilt from the documents holds the same values bit for bit.
//
// Body: {"row": {column: value, ...}, "children": {table: [{...}, ...]}}
// where a value is null, a number, a string, {"$ref": uuid} (a foreign key),
// {"$blob": sha256, "size": n} (stored once on the server) or {"$hex": "..."}
// (a small blob), or {"$real": "inf" | "-inf"}.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "storage/project/project_sqlite.h"

namespace rockface::storage::office {

struct BlobSource {
  std::string sha256;
  std::int64_t size = 0;
  std::string table, column;
  std::int64_t rowid = 0;
};

struct RecordDocument {
  std::string kind, uuid;
  std::int64_t local_id = 0;
  std::optional<std::int64_t> visit_id;  // local id of the visit it belongs to
  std::string body;                      // the JSON text (keys sorted)
  std::string content_sha256;            // of kind and body
  std::vector<BlobSource> blobs;
};

struct ProjectDocuments {
  std::string project_uuid, project_name;
  std::string tunnel_name;              // empty when the project has no tunnel
  std::vector<RecordDocument> records;  // in record_kinds() order, then local id
  struct VisitInfo {
    std::string uuid, started_at;
  };
  std::map<std::int64_t, VisitInfo> visits;  // by local id
};

// Reads every record of an open project (schema 6 or later) in one read
// transaction. Blob hashes come from the project's sync_blob cache, else
// are computed by reading the blob in pieces and then cached (the only
// write).
ProjectDocuments read_project_documents(sqlite::Connection& db);

}  // namespace rockface::storage::office
