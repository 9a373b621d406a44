#pragma once
// A byte stream too large for one blob stored as numbered parts, each row of
// a parts table holding the next kPartBytes of it (the last one fewer). A
// 30-million-point mesh is 1.8 GB, where SQLite refuses a blob over 1 GB and
// builds a blob's whole record in memory when it is written: parts of a few
// megabytes are written and read one at a time, so a stream is never held
// whole beside what it encodes. The table: (<owner column> INTEGER,
// idx INTEGER, bytes BLOB), idx counting from 0 (schema 11's model_mesh_part).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "storage/project/project_sqlite.h"

namespace rockface::storage::parts {

// 8 MiB: large enough that a 1.8 GB stream is a few hundred rows, small
// enough that the one part in memory is nothing beside the mesh.
constexpr std::size_t kPartBytes = std::size_t{8} << 20;

// The parts table of a record's stream, by the table and column the stream
// belongs to; a column stored whole (a photograph) has none.
struct PartsTable {
  const char* table;         // "model_mesh_part"
  const char* owner_column;  // "model_id": the record's id
};
// model.mesh -> model_mesh_part; nullptr for every other column.
const PartsTable* parts_table_of(const std::string& table, const std::string& column);

// Appends bytes to a record's stream, writing a part whenever kPartBytes are
// gathered; finish() writes the last one. Run inside the caller's write
// transaction. The record must have no parts yet.
class PartWriter {
 public:
  PartWriter(sqlite::Connection& db, const PartsTable& parts, std::int64_t owner);
  void append(const void* bytes, std::size_t n);
  void finish();
  std::uint64_t written() const { return written_; }

 private:
  void flush();
  sqlite::Connection& db_;
  sqlite::Statement insert_;
  std::int64_t owner_;
  std::int64_t next_idx_ = 0;
  std::vector<std::uint8_t> part_;
  std::uint64_t written_ = 0;
};

// Reads a record's stream: its size without loading it, then any range of
// it (the office hashes and sends it in the server's chunks), part by part
// through sqlite3_blob_open, so no more than the range asked is read.
class PartsReader {
 public:
  PartsReader(sqlite::Connection& db, const PartsTable& parts, std::int64_t owner,
              std::string where);
  std::uint64_t size() const { return size_; }
  bool empty() const { return rowids_.empty(); }
  // Bytes [offset, offset + out.size()); throws if past the end.
  void read(std::uint64_t offset, std::span<std::uint8_t> out) const;

 private:
  sqlite::Connection& db_;
  std::string table_;
  std::string where_;
  std::vector<std::int64_t> rowids_;
  std::vector<std::uint64_t> starts_;  // each part's first byte in the stream
  std::uint64_t size_ = 0;
};

}  // namespace rockface::storage::parts
