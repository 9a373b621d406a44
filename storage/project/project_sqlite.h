#pragma once
// A thin RAII layer over the SQLite3 C API for the project store: one
// connection, prepared statements, write transactions, and errors turned into
// rockface::Error messages that name the project file and say in plain words
// what went wrong (disk full, I/O error, file moved, damaged, busy).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace rockface::storage::sqlite {

// Throws rockface::Error (or InputError for a damaged / foreign file) for a
// failed SQLite call: "<file>: <doing>: <reason in plain words> (sqlite: ...)".
[[noreturn]] void fail(sqlite3* db, int rc, const std::filesystem::path& file,
                       std::string_view doing);

// Plain words for an SQLite (extended) result code.
std::string explain(int extended_rc);

class Connection {
 public:
  // immutable_media: read-only access to a file on write-protected media
  // (SD card lock switch, read-only mount). SQLite then reads the file as
  // it is, without the -shm/-wal side files it could not create there.
  enum class Access { read_only, read_write, read_write_create, immutable_media };
  // vfs: name of a registered SQLite VFS, empty for the default one.
  Connection(const std::filesystem::path& file, Access access, const std::string& vfs = {});
  // true when SQLite could open the file for reading only (write-protected).
  bool is_read_only() const;
  ~Connection();
  Connection(Connection&& other) noexcept;
  Connection& operator=(Connection&& other) noexcept;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  sqlite3* handle() const { return db_; }
  const std::filesystem::path& file() const { return file_; }

  // Runs one or more statements without results.
  void exec(std::string_view sql, std::string_view doing);
  // The first column of the first row of a query, as integer / text.
  std::int64_t query_int(std::string_view sql, std::string_view doing);
  std::string query_text(std::string_view sql, std::string_view doing);
  std::int64_t last_insert_id() const;

  // The first `count` bytes of the file as stored (fewer when the file is
  // shorter), read through this connection's own file handle, so that no
  // second descriptor of the file is opened and closed. Closing any
  // descriptor of a file drops every POSIX lock this process holds on it,
  // those of its other SQLite connections included (SQLite keeps its own
  // descriptors open until its locks are gone; a plain open and close does
  // not), and a project whose locks were dropped is checkpointed and its
  // write-ahead log deleted by another program while this one still uses
  // it: the two then write different logs into one file and damage it.
  std::vector<std::uint8_t> read_start(std::size_t count);
  // The main file's length in bytes, through the same open descriptor.
  std::int64_t size_on_disk();

  void close() noexcept;

 private:
  sqlite3* db_ = nullptr;
  std::filesystem::path file_;
};

class Statement {
 public:
  Statement(Connection& db, std::string_view sql, std::string_view doing);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  // Parameters are 1-based as in SQLite.
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind_null(int index);
  // The bytes must outlive step(): they are not copied (large images).
  Statement& bind_blob(int index, std::span<const std::uint8_t> bytes);
  template <typename T>
  Statement& bind(int index, const std::optional<T>& value) {
    if (value) return bind(index, *value);
    return bind_null(index);
  }
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, bool value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const std::string& text) {
    return bind(index, std::string_view(text));
  }

  // true while a row is available; false when done.
  bool step();
  // Runs a statement that returns no rows (INSERT, UPDATE ...).
  void run();
  void reset();

  bool is_null(int column) const;
  std::int64_t column_int(int column) const;
  double column_double(int column) const;
  std::string column_text(int column) const;
  std::vector<std::uint8_t> column_blob(int column) const;
  std::optional<std::int64_t> column_optional_int(int column) const;
  std::optional<double> column_optional_double(int column) const;

 private:
  Connection& db_;
  sqlite3_stmt* stmt_ = nullptr;
  std::string doing_;
};

// The columns of a statement's current row, read left to right: a record's
// mapping then lists its fields in the order of its SELECT, with no column
// numbers to keep in step with it. One reader per row.
class RowReader {
 public:
  explicit RowReader(const Statement& st) : st_(st) {}

  std::int64_t next_int64() { return st_.column_int(next_++); }
  int next_int() { return static_cast<int>(st_.column_int(next_++)); }
  bool next_bool() { return st_.column_int(next_++) != 0; }
  double next_double() { return st_.column_double(next_++); }
  std::string next_text() { return st_.column_text(next_++); }
  std::vector<std::uint8_t> next_blob() { return st_.column_blob(next_++); }
  std::optional<std::int64_t> next_optional_int64() { return st_.column_optional_int(next_++); }
  std::optional<double> next_optional_double() { return st_.column_optional_double(next_++); }
  // Whether the next column is NULL, without reading it.
  bool next_is_null() const { return st_.is_null(next_); }
  void skip(int columns) { next_ += columns; }

 private:
  const Statement& st_;
  int next_ = 0;
};

// BEGIN IMMEDIATE ... COMMIT. Taking the write lock at BEGIN (not at the first
// write) means a busy project is waited for by the busy timeout instead of
// failing half-way with SQLITE_BUSY. Rolls back when destroyed uncommitted.
// Opened inside another write it is a savepoint of that one.
class WriteTransaction {
 public:
  WriteTransaction(Connection& db, std::string_view doing);
  ~WriteTransaction();
  WriteTransaction(const WriteTransaction&) = delete;
  WriteTransaction& operator=(const WriteTransaction&) = delete;
  void commit();

 private:
  Connection& db_;
  std::string doing_;
  bool open_ = false;
  bool nested_ = false;  // a savepoint inside an open write
};

// A read snapshot (BEGIN ... COMMIT) so that a load made of several queries
// sees one consistent state while another connection writes.
class ReadTransaction {
 public:
  explicit ReadTransaction(Connection& db);
  ~ReadTransaction();
  ReadTransaction(const ReadTransaction&) = delete;
  ReadTransaction& operator=(const ReadTransaction&) = delete;

 private:
  Connection& db_;
  bool open_ = false;
};

}  // namespace rockface::storage::sqlite
