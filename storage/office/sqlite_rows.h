#pragma once
// Generic access to a project's rows for the sync (any table, any column,
// by name and SQLite type), over the project store's connection: the sync
// sends rows as they are stored, so that a pulled project holds the same
// values bit for bit, and a column added by a later schema travels without
// a change here.
#include <sqlite3.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "storage/project/blob_parts.h"
#include "storage/project/project_sqlite.h"

namespace rockface::storage::office {

// A prepared statement with column access by type (sqlite3 C API).
class RawStatement {
 public:
  RawStatement(sqlite::Connection& db, const std::string& sql, const std::string& doing);
  ~RawStatement();
  RawStatement(const RawStatement&) = delete;
  RawStatement& operator=(const RawStatement&) = delete;
  bool step();
  void reset();
  // Reset for another row, a failure then said as `doing` (a statement
  // prepared once and stepped for many records).
  void reset(const std::string& doing);
  sqlite3_stmt* get() const { return st_; }
  int columns() const { return sqlite3_column_count(st_); }
  std::string name(int c) const { return sqlite3_column_name(st_, c); }
  int type(int c) const { return sqlite3_column_type(st_, c); }
  std::int64_t int64(int c) const { return sqlite3_column_int64(st_, c); }
  std::string text(int c) const;
  void bind_text(int i, const std::string& v);
  void bind_int64(int i, std::int64_t v);
  void bind_null(int i);

 private:
  sqlite::Connection& db_;
  sqlite3_stmt* st_ = nullptr;
  std::string doing_;
};

// Foreign keys of a table: column -> (referenced table, referenced column).
struct ForeignKey {
  std::string column, table, to;
};
std::vector<ForeignKey> foreign_keys(sqlite::Connection& db, const std::string& table);
std::vector<std::string> column_names(sqlite::Connection& db, const std::string& table);

// Reads a blob column of one row in pieces of `chunk` bytes
// (sqlite3_blob_open), so that a photograph is never held whole. A column
// whose bytes are stored in parts (a model's mesh since schema 11:
// storage/project/blob_parts.h) is read from its parts when the column is
// empty, so the office gets the same bytes from either layout.
class BlobReader {
 public:
  BlobReader(sqlite::Connection& db, const std::string& table, const std::string& column,
             std::int64_t rowid);
  ~BlobReader();
  BlobReader(const BlobReader&) = delete;
  BlobReader& operator=(const BlobReader&) = delete;
  std::int64_t size() const { return size_; }
  // Reads bytes [offset, offset + out.size()).
  void read(std::int64_t offset, std::vector<std::uint8_t>& out);

 private:
  sqlite::Connection& db_;
  sqlite3_blob* blob_ = nullptr;
  std::optional<parts::PartsReader> parts_;
  std::int64_t size_ = 0;
  std::string where_;
};

// Writes a blob column of one row (made with zeroblob(size)) in pieces.
class BlobWriter {
 public:
  BlobWriter(sqlite::Connection& db, const std::string& table, const std::string& column,
             std::int64_t rowid);
  ~BlobWriter();
  BlobWriter(const BlobWriter&) = delete;
  BlobWriter& operator=(const BlobWriter&) = delete;
  void write(std::int64_t offset, const std::uint8_t* bytes, std::size_t n);

 private:
  sqlite::Connection& db_;
  sqlite3_blob* blob_ = nullptr;
  std::string where_;
};

std::string hex_of(const std::uint8_t* bytes, std::size_t n);
std::vector<std::uint8_t> bytes_of_hex(const std::string& hex, const std::string& where);

}  // namespace rockface::storage::office
