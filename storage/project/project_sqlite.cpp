#include "storage/project/project_sqlite.h"

#include <sqlite3.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "core/common/error.h"

namespace rockface::storage::sqlite {

std::string explain(int extended_rc) {
  switch (extended_rc) {
    case SQLITE_READONLY_DBMOVED:
      return "the project file was moved or deleted while it was open; nothing of this action "
             "was saved (open the project again where it is now)";
    case SQLITE_IOERR_FSYNC:
    case SQLITE_IOERR_DIR_FSYNC:
      return "input/output error: the storage card did not confirm the save; the action is "
             "either kept whole or not at all (reopen the project to see which)";
    case SQLITE_READONLY_ROLLBACK:
      return "the project holds an unfinished change that only a writable opening can undo";
    default:
      break;
  }
  switch (extended_rc & 0xff) {
    case SQLITE_FULL:
      return "the storage card is full (or the project reached its size limit); nothing of this "
             "action was saved";
    case SQLITE_IOERR:
      return "input/output error on the storage card; nothing of this action was saved";
    case SQLITE_CORRUPT:
      return "the project file is damaged";
    case SQLITE_NOTADB:
      return "not a rockface project (not an SQLite database)";
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return "the project stayed busy past the wait limit (another program or thread kept "
             "writing to it: `rockface ui` or a verb on the same project); nothing of this "
             "action was saved: run it again once the other one has finished saving";
    case SQLITE_READONLY:
      return "the project file cannot be written (read-only file, folder or card)";
    case SQLITE_CANTOPEN:
      return "the file cannot be opened (missing, a folder, or no permission)";
    case SQLITE_PERM:
    case SQLITE_AUTH:
      return "no permission to access the project file";
    case SQLITE_NOMEM:
      return "out of memory";
    case SQLITE_CONSTRAINT:
      return "the record refers to something the project does not hold, or repeats a unique name";
    case SQLITE_TOOBIG:
      return "a value is too large to store";
    default:
      return sqlite3_errstr(extended_rc);
  }
}

void fail(sqlite3* db, int rc, const std::filesystem::path& file, std::string_view doing) {
  int extended = rc;
  std::string detail = sqlite3_errstr(rc);
  if (db != nullptr) {
    extended = sqlite3_extended_errcode(db);
    if ((extended & 0xff) != (rc & 0xff)) extended = rc;
    detail = sqlite3_errmsg(db);
  }
  std::string reason = std::string(doing) + ": " + explain(extended) + " (sqlite: " + detail + ")";
  const int primary = extended & 0xff;
  if (primary == SQLITE_CORRUPT || primary == SQLITE_NOTADB)
    throw InputError(file.string(), std::move(reason));
  throw Error(file.string() + ": " + reason);
}

namespace {
int open_flags(Connection::Access access) {
  // NOMUTEX: one connection per thread (DESIGN.md "Threads"), so SQLite's
  // per-connection mutex is not needed.
  int flags = SQLITE_OPEN_NOMUTEX;
  switch (access) {
    case Connection::Access::read_only:
      return flags | SQLITE_OPEN_READONLY;
    case Connection::Access::read_write:
      return flags | SQLITE_OPEN_READWRITE;
    case Connection::Access::read_write_create:
      return flags | SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
    case Connection::Access::immutable_media:
      return flags | SQLITE_OPEN_READONLY | SQLITE_OPEN_URI;
  }
  return flags;
}
}  // namespace

Connection::Connection(const std::filesystem::path& file, Access access, const std::string& vfs)
    : file_(file) {
  std::string name = file.string();
  if (access == Access::immutable_media) {
    // A URI filename (https://sqlite.org/uri.html): escape what URIs reserve.
    std::string uri = "file:";
    for (char c : name) {
      if (c == '%' || c == '?' || c == '#') {
        char hex[4];
        std::snprintf(hex, sizeof(hex), "%%%02X", static_cast<unsigned char>(c));
        uri += hex;
      } else {
        uri += c;
      }
    }
    name = uri + "?immutable=1";
  }
  const int rc =
      sqlite3_open_v2(name.c_str(), &db_, open_flags(access), vfs.empty() ? nullptr : vfs.c_str());
  if (rc != SQLITE_OK) {
    sqlite3* db = db_;
    db_ = nullptr;
    std::string detail = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    const int extended = db ? sqlite3_extended_errcode(db) : rc;
    sqlite3_close_v2(db);
    throw Error(file.string() + ": opening: " + explain(extended) + " (sqlite: " + detail + ")");
  }
  sqlite3_extended_result_codes(db_, 1);
}

Connection::~Connection() {
  close();
}

bool Connection::is_read_only() const {
  return sqlite3_db_readonly(db_, "main") == 1;
}

Connection::Connection(Connection&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)), file_(std::move(other.file_)) {}

Connection& Connection::operator=(Connection&& other) noexcept {
  if (this != &other) {
    close();
    db_ = std::exchange(other.db_, nullptr);
    file_ = std::move(other.file_);
  }
  return *this;
}

void Connection::close() noexcept {
  // close_v2 defers the close until unfinalised statements are gone instead
  // of failing; the store finalises every statement it makes anyway.
  if (db_ != nullptr) sqlite3_close_v2(db_);
  db_ = nullptr;
}

void Connection::exec(std::string_view sql, std::string_view doing) {
  const std::string text(sql);
  const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, nullptr);
  if (rc != SQLITE_OK) fail(db_, rc, file_, doing);
}

std::int64_t Connection::query_int(std::string_view sql, std::string_view doing) {
  Statement st(*this, sql, doing);
  if (!st.step()) return 0;
  return st.column_int(0);
}

std::string Connection::query_text(std::string_view sql, std::string_view doing) {
  Statement st(*this, sql, doing);
  if (!st.step()) return {};
  return st.column_text(0);
}

std::int64_t Connection::last_insert_id() const {
  return sqlite3_last_insert_rowid(db_);
}

namespace {

sqlite3_file* main_file(sqlite3* db, const std::filesystem::path& path, std::string_view doing) {
  sqlite3_file* file = nullptr;
  const int rc = sqlite3_file_control(db, "main", SQLITE_FCNTL_FILE_POINTER, &file);
  if (rc != SQLITE_OK) fail(nullptr, rc, path, doing);
  if (file == nullptr || file->pMethods == nullptr) fail(nullptr, SQLITE_CANTOPEN, path, doing);
  return file;
}

}  // namespace

std::int64_t Connection::size_on_disk() {
  const std::string_view doing = "reading the file's length";
  sqlite3_file* file = main_file(db_, file_, doing);
  sqlite3_int64 size = 0;
  const int rc = file->pMethods->xFileSize(file, &size);
  if (rc != SQLITE_OK) fail(nullptr, rc, file_, doing);
  return size;
}

std::vector<std::uint8_t> Connection::read_start(std::size_t count) {
  const std::string_view doing = "reading the file's header";
  sqlite3_file* file = main_file(db_, file_, doing);
  sqlite3_int64 size = 0;
  int rc = file->pMethods->xFileSize(file, &size);
  if (rc != SQLITE_OK) fail(nullptr, rc, file_, doing);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(
      std::clamp<sqlite3_int64>(size, 0, static_cast<sqlite3_int64>(count))));
  if (out.empty()) return out;
  rc = file->pMethods->xRead(file, out.data(), static_cast<int>(out.size()), 0);
  if (rc != SQLITE_OK) fail(nullptr, rc, file_, doing);
  return out;
}

Statement::Statement(Connection& db, std::string_view sql, std::string_view doing)
    : db_(db), doing_(doing) {
  const int rc =
      sqlite3_prepare_v2(db.handle(), sql.data(), static_cast<int>(sql.size()), &stmt_, nullptr);
  if (rc != SQLITE_OK) fail(db.handle(), rc, db.file(), doing_);
}

Statement::~Statement() {
  sqlite3_finalize(stmt_);
}

Statement& Statement::bind(int index, std::int64_t value) {
  const int rc = sqlite3_bind_int64(stmt_, index, value);
  if (rc != SQLITE_OK) fail(db_.handle(), rc, db_.file(), doing_);
  return *this;
}

Statement& Statement::bind(int index, double value) {
  const int rc = sqlite3_bind_double(stmt_, index, value);
  if (rc != SQLITE_OK) fail(db_.handle(), rc, db_.file(), doing_);
  return *this;
}

Statement& Statement::bind(int index, std::string_view text) {
  const int rc =
      sqlite3_bind_text64(stmt_, index, text.data(), text.size(), SQLITE_TRANSIENT, SQLITE_UTF8);
  if (rc != SQLITE_OK) fail(db_.handle(), rc, db_.file(), doing_);
  return *this;
}

Statement& Statement::bind_null(int index) {
  const int rc = sqlite3_bind_null(stmt_, index);
  if (rc != SQLITE_OK) fail(db_.handle(), rc, db_.file(), doing_);
  return *this;
}

Statement& Statement::bind_blob(int index, std::span<const std::uint8_t> bytes) {
  // A zero-length blob is stored as an empty blob, not NULL: sqlite3 treats a
  // null data pointer as NULL, so point at something valid.
  static const std::uint8_t kNothing = 0;
  const void* data = bytes.empty() ? &kNothing : bytes.data();
  const int rc = sqlite3_bind_blob64(stmt_, index, data, bytes.size(), SQLITE_STATIC);
  if (rc != SQLITE_OK) fail(db_.handle(), rc, db_.file(), doing_);
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(db_.handle(), rc, db_.file(), doing_);
}

void Statement::run() {
  while (step()) {
  }
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

bool Statement::is_null(int column) const {
  return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
}

std::int64_t Statement::column_int(int column) const {
  return sqlite3_column_int64(stmt_, column);
}

double Statement::column_double(int column) const {
  return sqlite3_column_double(stmt_, column);
}

std::string Statement::column_text(int column) const {
  const auto* text = sqlite3_column_text(stmt_, column);
  if (text == nullptr) return {};
  const int n = sqlite3_column_bytes(stmt_, column);
  return std::string(reinterpret_cast<const char*>(text), static_cast<std::size_t>(n));
}

std::vector<std::uint8_t> Statement::column_blob(int column) const {
  const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(stmt_, column));
  const int n = sqlite3_column_bytes(stmt_, column);
  if (data == nullptr || n <= 0) return {};
  return std::vector<std::uint8_t>(data, data + n);
}

std::optional<std::int64_t> Statement::column_optional_int(int column) const {
  if (is_null(column)) return std::nullopt;
  return column_int(column);
}

std::optional<double> Statement::column_optional_double(int column) const {
  if (is_null(column)) return std::nullopt;
  return column_double(column);
}

WriteTransaction::WriteTransaction(Connection& db, std::string_view doing)
    : db_(db), doing_(doing) {
  // Inside another write (ProjectStore::in_one_transaction) a save is a
  // savepoint of it: it commits with the outer one or not at all.
  nested_ = sqlite3_get_autocommit(db_.handle()) == 0;
  db_.exec(nested_ ? "SAVEPOINT nested_write" : "BEGIN IMMEDIATE", doing_);
  open_ = true;
}

WriteTransaction::~WriteTransaction() {
  if (!open_) return;
  if (nested_)
    sqlite3_exec(db_.handle(), "ROLLBACK TO nested_write; RELEASE nested_write", nullptr, nullptr,
                 nullptr);
  else
    sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void WriteTransaction::commit() {
  const int rc = sqlite3_exec(db_.handle(), nested_ ? "RELEASE nested_write" : "COMMIT", nullptr,
                              nullptr, nullptr);
  if (rc != SQLITE_OK) {
    // A failed COMMIT (disk full, I/O error) may leave the transaction open;
    // the destructor rolls it back so the connection stays usable.
    fail(db_.handle(), rc, db_.file(), doing_);
  }
  open_ = false;
}

ReadTransaction::ReadTransaction(Connection& db) : db_(db) {
  // Inside a write transaction (a save that reads back) the snapshot is
  // already the writer's own.
  if (sqlite3_get_autocommit(db_.handle()) == 0) return;
  db_.exec("BEGIN", "starting a read");
  open_ = true;
}

ReadTransaction::~ReadTransaction() {
  if (open_) sqlite3_exec(db_.handle(), "COMMIT", nullptr, nullptr, nullptr);
}

}  // namespace rockface::storage::sqlite
