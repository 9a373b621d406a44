#pragma once
// Which records of a project go to the office server, in the order a
// project is rebuilt from them (a record refers only to kinds before it):
// one kind per project table with its own rows, with the tables that only
// hold a record's parts (a capture's settings, a tunnel's stations) sent
// inside their record as children. A record's identity is its UUID (schema
// 6); the tunnel and a visit's placement, which a project replaces in place,
// take their project's and visit's UUID, so a replacement is a new revision
// of the same record.
#include <string>
#include <vector>

namespace rockface::storage::office {

struct ChildTable {
  const char* table;
  const char* parent_column;  // refers to the record's local id
};

struct RecordKind {
  const char* kind;  // the project table
  // SQL over alias t: the record's UUID, the local id of the visit it
  // belongs to (NULL: the project's), and its local id (what orders it).
  const char* uuid_sql;
  const char* visit_sql;
  const char* local_id_sql;
  std::vector<ChildTable> children;
  // Columns sent as blobs stored once by SHA-256 (photographs, meshes); the
  // record's row id is t.id. Other blob columns travel inline as hex.
  std::vector<const char*> stored_blobs;
};

const std::vector<RecordKind>& record_kinds();
const RecordKind* find_record_kind(const std::string& kind);

}  // namespace rockface::storage::office
