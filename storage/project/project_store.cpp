#include "storage/project/project_store.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <ctime>
#include <utility>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store_rows.h"
#include "storage/project/visit_geologist.h"

namespace rockface::storage {

namespace fs = std::filesystem;
using namespace rows;  // row helpers and the SQLite wrappers

std::string utc_now_iso8601() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()) % 1000;
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%S", &tm);
  char out[40];
  std::snprintf(out, sizeof(out), "%s.%03dZ", text, static_cast<int>(ms.count()));
  return out;
}

namespace {

constexpr const char* kCreatedBy = "rockface 0.1";

// That `file` is there, a file and readable, from its directory entry only:
// no descriptor of it is opened here (see check_header).
void check_path(const fs::path& file) {
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (ec || !fs::exists(status)) throw InputError(file.string(), "no such project file");
  if (fs::is_directory(status)) throw InputError(file.string(), "is a folder, not a project file");
  if (::access(file.c_str(), R_OK) != 0)
    throw InputError(file.string(), "cannot be read (no permission?)");
}

// What the first 100 bytes of an SQLite file say (https://sqlite.org/fileformat.html
// "The Database Header"), checked before SQLite reads anything else of the
// file: a foreign file is recognised before it is used.
// The bytes are read through the probe's own file handle, never by opening
// the file again: closing that second descriptor would drop the POSIX locks
// of every connection this process has open on the project (the UI's store
// while a worker opens another one), and another program ending its write
// would then take this process for gone, checkpoint the write-ahead log into
// the file and delete it while this process still writes into it: two logs,
// one file, damaged (the lost-lock case of https://sqlite.org/howtocorrupt.html,
// section 2.2).
void check_header(Connection& probe) {
  const std::string file = probe.file().string();
  const std::vector<std::uint8_t> header = probe.read_start(100);
  if (header.empty()) throw InputError(file, "empty file, not a rockface project");
  static constexpr char kMagic[16] = "SQLite format 3";  // with its terminating NUL
  if (header.size() < 100 || std::memcmp(header.data(), kMagic, sizeof(kMagic)) != 0)
    throw InputError(file, "not a rockface project (not an SQLite database)");
  const std::uint32_t app_id = (std::uint32_t{header[68]} << 24) |
                               (std::uint32_t{header[69]} << 16) |
                               (std::uint32_t{header[70]} << 8) | std::uint32_t{header[71]};
  if (app_id != static_cast<std::uint32_t>(schema::kApplicationId)) {
    char hex[16];
    std::snprintf(hex, sizeof(hex), "0x%08x", app_id);
    throw InputError(file, std::string("not a rockface project (an SQLite database of "
                                       "another program: application_id ") +
                               hex + ")");
  }
}

void configure_reader(Connection& db, const OpenOptions& options) {
  sqlite3_busy_timeout(db.handle(), static_cast<int>(options.busy_timeout.count()));
}

void configure_writer(Connection& db, const OpenOptions& options) {
  configure_reader(db, options);
  db.exec("PRAGMA foreign_keys = ON", "opening the project");
  // FULL: a commit is on the card when save_* returns (WAL + NORMAL could
  // lose the last saves on power loss, which is what a flat battery is).
  db.exec("PRAGMA synchronous = FULL", "opening the project");
  db.exec("PRAGMA cell_size_check = ON", "opening the project");
  if (db.query_text("PRAGMA journal_mode = WAL", "opening the project") != "wal")
    throw Error(db.file().string() +
                ": opening the project: the file system does not support SQLite's write-ahead "
                "log (WAL)");
  // The write-ahead log grows to the largest save (a capture is ~20 MB) and
  // would keep that size on the card; past 32 MiB it is cut back after each
  // checkpoint.
  db.exec("PRAGMA journal_size_limit = 33554432", "opening the project");
  if (options.max_file_bytes > 0) {
    const std::int64_t page = db.query_int("PRAGMA page_size", "opening the project");
    db.exec("PRAGMA max_page_count = " +
                std::to_string(std::max<std::int64_t>(1, options.max_file_bytes / page)),
            "opening the project");
  }
}

// The -wal and -shm files a read-only connection left beside `file` when it
// closed: SQLite makes them for a read-only connection's reads of a WAL
// project, and a read-only connection cannot remove them (it cannot
// checkpoint). They are removed as SQLite removes them: by a writable
// connection that reads and is the last one to close (it checkpoints an
// empty log, writing nothing into the file, and deletes both). Left alone
// when the log holds anything (another program wrote: its saves), when
// another connection still has the project open (SQLite then keeps them),
// when a rollback journal lies beside it, or when the file cannot be
// written.
void remove_log_files(const fs::path& file) noexcept {
  try {
    std::error_code ec;
    const fs::path wal = file.string() + "-wal";
    const auto size = fs::file_size(wal, ec);
    if (ec || size != 0) return;
    // A rollback journal beside it would be undone by a writable opening.
    if (fs::exists(file.string() + "-journal", ec) || ec) return;
    Connection db(file, Connection::Access::read_write);
    if (db.is_read_only()) return;
    db.query_int("PRAGMA schema_version", "closing the project");
    db.close();
  } catch (...) {
    // Only tidying: the project was read, nothing of it depends on this.
  }
}

void fsync_directory(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace
// ---------------------------------------------------------------- opening

ProjectStore::ProjectStore(fs::path file, Connection db, bool read_only,
                           std::string read_only_reason, int schema_version)
    : file_(std::move(file)),
      db_(std::move(db)),
      read_only_(read_only),
      read_only_reason_(std::move(read_only_reason)),
      schema_version_(schema_version) {
  struct stat st {};
  if (::stat(file_.c_str(), &st) == 0) {
    device_ = st.st_dev;
    inode_ = st.st_ino;
  }
}

ProjectStore::ProjectStore(ProjectStore&&) noexcept = default;
ProjectStore& ProjectStore::operator=(ProjectStore&&) noexcept = default;

ProjectStore::~ProjectStore() {
  // A read-only store (a verb that only reads, refused or not) leaves
  // nothing beside the project: see remove_log_files (issue 41).
  if (read_only_ && db_.handle() != nullptr) {
    db_.close();
    remove_log_files(file_);
  }
}

ProjectStore ProjectStore::create(const fs::path& file, const ProjectInfo& info,
                                  const OpenOptions& options) {
  if (options.read_only) throw InputError(file.string(), "cannot create a project read-only");
  std::error_code ec;
  if (fs::exists(file, ec)) throw InputError(file.string(), "already exists");
  require_finite(info.datum, "project datum");
  fs::path temp = file;
  temp += ".creating-" + std::to_string(::getpid());
  fs::remove(temp, ec);
  try {
    Connection db(temp, Connection::Access::read_write_create, options.vfs);
    db.exec("PRAGMA foreign_keys = ON", "creating the project");
    schema::create_version_1(db);
    schema::migrate_to_current(db);
    {
      WriteTransaction tx(db, "creating the project");
      Statement st(db,
                   "INSERT INTO project (id, name, datum_x, datum_y, datum_z, datum_crs, "
                   "created_at, created_by) VALUES (1, ?, ?, ?, ?, ?, ?, ?)",
                   "creating the project");
      st.bind(1, info.name)
          .bind(2, info.datum.x())
          .bind(3, info.datum.y())
          .bind(4, info.datum.z())
          .bind(5, info.datum_crs)
          .bind(6, or_now(info.created_at))
          .bind(7, info.created_by.empty() ? std::string(kCreatedBy) : info.created_by);
      st.run();
      Statement log(db,
                    "INSERT INTO action_log (at, visit_id, action, detail) VALUES (?, NULL, "
                    "'project created', ?)",
                    "creating the project");
      log.bind(1, utc_now_iso8601()).bind(2, info.name);
      log.run();
      tx.commit();
    }
    db.exec("PRAGMA synchronous = FULL", "creating the project");
    if (db.query_text("PRAGMA journal_mode = WAL", "creating the project") != "wal")
      throw Error(file.string() +
                  ": creating the project: the file system does not support SQLite's "
                  "write-ahead log (WAL)");
    db.close();  // the last connection checkpoints and removes the -wal file
  } catch (...) {
    fs::remove(temp, ec);
    fs::remove(fs::path(temp.string() + "-wal"), ec);
    fs::remove(fs::path(temp.string() + "-shm"), ec);
    throw;
  }
  // link() fails if the name was taken meanwhile: never overwrite a file.
  if (::link(temp.c_str(), file.c_str()) != 0) {
    const int err = errno;
    fs::remove(temp, ec);
    throw InputError(file.string(),
                     std::string("cannot create the project file: ") + std::strerror(err));
  }
  fs::remove(temp, ec);
  fsync_directory(file.parent_path());
  return open(file, options);
}

namespace {
bool on_read_only_media(const fs::path& file) {
  struct statvfs vfs {};
  return ::statvfs(file.c_str(), &vfs) == 0 && (vfs.f_flag & ST_RDONLY) != 0;
}
}  // namespace

ProjectStore ProjectStore::open(const fs::path& file, const OpenOptions& options) {
  check_path(file);
  const bool media_read_only = on_read_only_media(file);
  // A rollback journal with content next to the file is an interrupted
  // change of a project in rollback mode (a file not written by this store:
  // it always uses WAL). SQLite undoes it at the first read, which needs
  // write access; the header, checked before that first read, shows the file
  // is a project, so a writable opening may do that when writing is allowed
  // at all.
  std::error_code ec;
  const fs::path journal = file.string() + "-journal";
  const bool hot_journal = fs::exists(journal, ec) && fs::file_size(journal, ec) > 0;
  const bool recover = hot_journal && !media_read_only && !options.read_only;
  int version = 0;
  {
    Connection probe(file,
                     media_read_only ? Connection::Access::immutable_media
                     : recover       ? Connection::Access::read_write
                                     : Connection::Access::read_only,
                     options.vfs);
    check_header(probe);
    configure_reader(probe, options);
    IntegrityReport report;
    try {
      report = check_project_pages(probe, options.check);
      if (report.ok) version = schema::version_of(probe);
    } catch (const InputError& e) {
      throw InputError(file.string(), "the project file is damaged and cannot be read (" +
                                          std::string(e.reason()) + ")");
    }
    if (!report.ok)
      throw InputError(file.string(),
                       "the project file is damaged (integrity check: " + report.problems.front() +
                           (report.problems.size() > 1 ? ", ..." : "") + "); it was not changed");
    if (version < 1) throw InputError(file.string(), "not a rockface project (no schema version)");
    std::string reason;
    if (version > schema::kCurrentVersion)
      reason = "written by a newer rockface (project schema " + std::to_string(version) +
               ", this program knows up to " + std::to_string(schema::kCurrentVersion) +
               "): opened read-only, nothing can be saved to it";
    else if (media_read_only)
      reason = "the card or folder is write-protected: opened read-only, nothing can be saved";
    else if (options.read_only)
      reason = "opened read-only on request";
    if (!reason.empty()) {
      if (version < schema::kCurrentVersion)
        throw InputError(file.string(),
                         "written by an older rockface (project schema " + std::to_string(version) +
                             ") and must be upgraded before it can be read: open it writable "
                             "once (keep a copy of the file first if an older rockface still "
                             "needs it)");
      return ProjectStore(file, std::move(probe), true, reason, version);
    }
  }
  Connection db(file, Connection::Access::read_write, options.vfs);
  if (db.is_read_only()) {
    // SQLite fell back to reading: the file itself is write-protected.
    configure_reader(db, options);
    if (version < schema::kCurrentVersion)
      throw InputError(file.string(), "written by an older rockface (project schema " +
                                          std::to_string(version) +
                                          ") and write-protected, so it cannot be upgraded");
    return ProjectStore(file, std::move(db), true,
                        "the project file is write-protected: opened read-only, nothing can be "
                        "saved",
                        version);
  }
  configure_writer(db, options);
  if (version < schema::kCurrentVersion) schema::migrate_to_current(db);
  version = schema::version_of(db);
  return ProjectStore(file, std::move(db), false, {}, version);
}

ProjectStore ProjectStore::open_or_create(const fs::path& file, const ProjectInfo& info,
                                          const OpenOptions& options) {
  std::error_code ec;
  if (fs::exists(file, ec)) return open(file, options);
  return create(file, info, options);
}

void ProjectStore::stop_writing(std::string reason) {
  read_only_ = true;
  read_only_reason_ = std::move(reason);
}

void ProjectStore::require_writable(const std::string& doing) const {
  if (read_only_) throw InputError(file_.string(), doing + ": " + read_only_reason_);
  struct stat st {};
  if (::stat(file_.c_str(), &st) != 0 || st.st_dev != device_ || st.st_ino != inode_)
    throw Error(file_.string() + ": " + doing + ": " + sqlite::explain(SQLITE_READONLY_DBMOVED));
}

RecordId ProjectStore::insert_log(std::optional<RecordId> visit_id, const std::string& action,
                                  const std::string& detail) {
  Statement st(db_, "INSERT INTO action_log (at, visit_id, action, detail) VALUES (?, ?, ?, ?)",
               "logging " + action);
  st.bind(1, utc_now_iso8601()).bind(2, visit_id).bind(3, action).bind(4, detail);
  st.run();
  return db_.last_insert_id();
}

// ---------------------------------------------------------------- project

ProjectInfo ProjectStore::project() {
  Statement st(db_,
               "SELECT name, datum_x, datum_y, datum_z, datum_crs, created_at, created_by FROM "
               "project WHERE id = 1",
               "reading the project");
  if (!st.step()) throw InputError(file_.string(), "the project record is missing");
  RowReader row(st);
  ProjectInfo info;
  info.name = row.next_text();
  info.datum = next_vector3(row);
  info.datum_crs = row.next_text();
  info.created_at = row.next_text();
  info.created_by = row.next_text();
  return info;
}

void ProjectStore::update_project(const ProjectInfo& info) {
  const std::string doing = "saving the project's name and datum";
  require_writable(doing);
  require_finite(info.datum, "project datum");
  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "UPDATE project SET name = ?, datum_x = ?, datum_y = ?, datum_z = ?, "
               "datum_crs = ? WHERE id = 1",
               doing);
  st.bind(1, info.name)
      .bind(2, info.datum.x())
      .bind(3, info.datum.y())
      .bind(4, info.datum.z())
      .bind(5, info.datum_crs);
  st.run();
  insert_log(std::nullopt, "project changed",
             info.name + ", datum " + format_fixed(info.datum.x(), 3) + " " +
                 format_fixed(info.datum.y(), 3) + " " + format_fixed(info.datum.z(), 3));
  tx.commit();
}

// ---------------------------------------------------------------- visits

void ProjectStore::in_one_transaction(const std::string& doing, const std::function<void()>& body) {
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  body();
  tx.commit();
}

RecordId ProjectStore::begin_visit(const std::string& source, const std::string& note,
                                   const std::string& geologist) {
  const std::string doing = "starting a visit";
  const std::string name = checked_geologist(geologist, "geologist");
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  Statement st(db_, "INSERT INTO visit (started_at, source, note) VALUES (?, ?, ?)", doing);
  st.bind(1, utc_now_iso8601()).bind(2, source).bind(3, note);
  st.run();
  const RecordId id = db_.last_insert_id();
  insert_log(id, "visit started", source);
  if (!name.empty()) put_visit_geologist(id, name, doing);
  tx.commit();
  return id;
}

std::vector<Visit> ProjectStore::list_visits() {
  Statement st(db_,
               "SELECT v.id, v.started_at, v.source, v.note, g.geologist FROM visit v "
               "LEFT JOIN visit_geologist g ON g.visit_id = v.id ORDER BY v.id",
               "listing visits");
  std::vector<Visit> out;
  while (st.step()) {
    RowReader row(st);
    Visit& v = out.emplace_back();
    v.id = row.next_int64();
    v.started_at = row.next_text();
    v.source = row.next_text();
    v.note = row.next_text();
    if (!st.is_null(4)) v.geologist = st.column_text(4);
  }
  return out;
}

std::optional<RecordId> ProjectStore::latest_visit() {
  Statement st(db_, "SELECT max(id) FROM visit", "finding the latest visit");
  if (!st.step() || st.is_null(0)) return std::nullopt;
  return st.column_int(0);
}

// ---------------------------------------------------------------- log

RecordId ProjectStore::log_action(std::optional<RecordId> visit_id, const std::string& action,
                                  const std::string& detail) {
  const std::string doing = "logging " + action;
  require_writable(doing);
  if (action.empty()) throw InputError("action log", "the action has no name");
  WriteTransaction tx(db_, doing);
  const RecordId id = insert_log(visit_id, action, detail);
  tx.commit();
  return id;
}

std::vector<ActionLogEntry> ProjectStore::list_actions(std::optional<RecordId> visit_id) {
  Statement st(db_,
               "SELECT id, at, visit_id, action, detail FROM action_log WHERE (?1 IS NULL OR "
               "visit_id = ?1) ORDER BY id",
               "listing the action log");
  st.bind(1, visit_id);
  std::vector<ActionLogEntry> out;
  while (st.step()) {
    RowReader row(st);
    ActionLogEntry& e = out.emplace_back();
    e.id = row.next_int64();
    e.at = row.next_text();
    e.visit_id = row.next_optional_int64();
    e.action = row.next_text();
    e.detail = row.next_text();
  }
  return out;
}

// ---------------------------------------------------------------- maintenance

IntegrityReport ProjectStore::check_integrity(OpenOptions::Check depth) {
  return check_project_pages(db_, depth);
}

void ProjectStore::checkpoint() {
  if (read_only_) return;
  db_.exec("PRAGMA wal_checkpoint(TRUNCATE)", "writing the log into the project file");
}

}  // namespace rockface::storage
