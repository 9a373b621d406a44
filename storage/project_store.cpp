#include "storage/project_store.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/project_blobs.h"
#include "storage/project_schema.h"

namespace rockface::storage {

namespace fs = std::filesystem;
using sqlite::Connection;
using sqlite::ReadTransaction;
using sqlite::Statement;
using sqlite::WriteTransaction;

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

std::string or_now(const std::string& stamp) {
  return stamp.empty() ? utc_now_iso8601() : stamp;
}

void require_finite(double value, const std::string& where) {
  if (!std::isfinite(value)) throw InputError(where, "must be a finite number");
}

void require_orientation(double dip, double dipdir, const std::string& where) {
  require_finite(dip, where + ".dip");
  require_finite(dipdir, where + ".dipdir");
  if (dip < 0 || dip > 90)
    throw InputError(where + ".dip", "must be in [0, 90] degrees, got " + std::to_string(dip));
  if (dipdir < 0 || dipdir >= 360)
    throw InputError(where + ".dipdir",
                     "must be in [0, 360) degrees, got " + std::to_string(dipdir));
}

void require_finite(const Eigen::Vector3d& p, const std::string& where) {
  if (!p.allFinite()) throw InputError(where, "must be finite coordinates");
}

// What the first 100 bytes of an SQLite file say (https://sqlite.org/fileformat.html
// "The Database Header"); read with plain file I/O so that a foreign file is
// recognised before SQLite touches it.
void check_header(const fs::path& file) {
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (ec || !fs::exists(status)) throw InputError(file.string(), "no such project file");
  if (fs::is_directory(status)) throw InputError(file.string(), "is a folder, not a project file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot be read (no permission?)");
  unsigned char header[100] = {};
  in.read(reinterpret_cast<char*>(header), sizeof(header));
  const auto got = in.gcount();
  if (got == 0) throw InputError(file.string(), "empty file, not a rockface project");
  static constexpr char kMagic[16] = "SQLite format 3";  // with its terminating NUL
  if (got < static_cast<std::streamsize>(sizeof(header)) ||
      std::memcmp(header, kMagic, sizeof(kMagic)) != 0)
    throw InputError(file.string(), "not a rockface project (not an SQLite database)");
  const std::uint32_t app_id = (std::uint32_t{header[68]} << 24) |
                               (std::uint32_t{header[69]} << 16) |
                               (std::uint32_t{header[70]} << 8) | std::uint32_t{header[71]};
  if (app_id != static_cast<std::uint32_t>(schema::kApplicationId)) {
    char hex[16];
    std::snprintf(hex, sizeof(hex), "0x%08x", app_id);
    throw InputError(file.string(), std::string("not a rockface project (an SQLite database of "
                                                "another program: application_id ") +
                                        hex + ")");
  }
}

IntegrityReport run_check(Connection& db, OpenOptions::Check depth) {
  IntegrityReport report;
  Statement st(
      db,
      depth == OpenOptions::Check::full ? "PRAGMA integrity_check(20)" : "PRAGMA quick_check(20)",
      "checking the project's integrity");
  while (st.step()) report.problems.push_back(st.column_text(0));
  report.ok = report.problems.size() == 1 && report.problems[0] == "ok";
  if (report.ok) report.problems.clear();
  return report;
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

std::string kind_text(Measurement::Kind kind) {
  switch (kind) {
    case Measurement::Kind::trace:
      return "trace";
    case Measurement::Kind::area:
      return "area";
    case Measurement::Kind::point_orientation:
      return "point_orientation";
  }
  return "trace";
}

Measurement::Kind kind_of(const std::string& text, const std::string& where) {
  if (text == "trace") return Measurement::Kind::trace;
  if (text == "area") return Measurement::Kind::area;
  if (text == "point_orientation") return Measurement::Kind::point_orientation;
  throw Error(where + ": unknown measurement kind '" + text + "'");
}

std::optional<RecordId> optional_id(const Statement& st, int column) {
  return st.column_optional_int(column);
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
ProjectStore::~ProjectStore() = default;

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
  check_header(file);
  const bool media_read_only = on_read_only_media(file);
  // A rollback journal with content next to the file is an interrupted
  // change of a project in rollback mode (a file not written by this store:
  // it always uses WAL). SQLite undoes it at the first read, which needs
  // write access; the header above already showed the file is a project, so
  // a writable opening may do that when writing is allowed at all.
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
    configure_reader(probe, options);
    IntegrityReport report;
    try {
      report = run_check(probe, options.check);
      version = schema::version_of(probe);
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
  ProjectInfo info;
  info.name = st.column_text(0);
  info.datum = {st.column_double(1), st.column_double(2), st.column_double(3)};
  info.datum_crs = st.column_text(4);
  info.created_at = st.column_text(5);
  info.created_by = st.column_text(6);
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
  char detail[160];
  std::snprintf(detail, sizeof(detail), "datum %.3f %.3f %.3f", info.datum.x(), info.datum.y(),
                info.datum.z());
  insert_log(std::nullopt, "project changed", info.name + ", " + detail);
  tx.commit();
}

// ---------------------------------------------------------------- visits

RecordId ProjectStore::begin_visit(const std::string& source, const std::string& note) {
  const std::string doing = "starting a visit";
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  Statement st(db_, "INSERT INTO visit (started_at, source, note) VALUES (?, ?, ?)", doing);
  st.bind(1, utc_now_iso8601()).bind(2, source).bind(3, note);
  st.run();
  const RecordId id = db_.last_insert_id();
  insert_log(id, "visit started", source);
  tx.commit();
  return id;
}

std::vector<Visit> ProjectStore::list_visits() {
  Statement st(db_, "SELECT id, started_at, source, note FROM visit ORDER BY id", "listing visits");
  std::vector<Visit> out;
  while (st.step())
    out.push_back({st.column_int(0), st.column_text(1), st.column_text(2), st.column_text(3)});
  return out;
}

std::optional<RecordId> ProjectStore::latest_visit() {
  Statement st(db_, "SELECT max(id) FROM visit", "finding the latest visit");
  if (!st.step() || st.is_null(0)) return std::nullopt;
  return st.column_int(0);
}

// ---------------------------------------------------------------- cameras

RecordId ProjectStore::save_camera_body(const CameraBody& body) {
  const std::string doing = "saving camera body " + body.make + " " + body.model;
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  Statement find(db_, "SELECT id FROM camera_body WHERE make = ? AND model = ? AND serial = ?",
                 doing);
  find.bind(1, body.make).bind(2, body.model).bind(3, body.serial);
  if (find.step()) return find.column_int(0);
  Statement st(db_, "INSERT INTO camera_body (make, model, serial) VALUES (?, ?, ?)", doing);
  st.bind(1, body.make).bind(2, body.model).bind(3, body.serial);
  st.run();
  const RecordId id = db_.last_insert_id();
  insert_log(
      std::nullopt, "camera body saved",
      "body " + std::to_string(id) + ": " + body.make + " " + body.model + " #" + body.serial);
  tx.commit();
  return id;
}

std::vector<CameraBody> ProjectStore::list_camera_bodies() {
  Statement st(db_, "SELECT id, make, model, serial FROM camera_body ORDER BY id",
               "listing camera bodies");
  std::vector<CameraBody> out;
  while (st.step())
    out.push_back({st.column_int(0), st.column_text(1), st.column_text(2), st.column_text(3)});
  return out;
}

RecordId ProjectStore::save_calibration(const Calibration& calibration) {
  const std::string doing = "saving a calibration";
  require_writable(doing);
  const auto& k = calibration.intrinsics;
  if (k.width <= 0 || k.height <= 0)
    throw InputError("calibration", "image size must be positive, got " + std::to_string(k.width) +
                                        " x " + std::to_string(k.height));
  for (auto [value, name] : {std::pair{k.fx, "fx"}, {k.fy, "fy"}, {k.cx, "cx"}, {k.cy, "cy"}}) {
    require_finite(value, std::string("calibration.") + name);
  }
  if (k.fx <= 0 || k.fy <= 0) throw InputError("calibration", "fx and fy must be positive");
  for (std::size_t i = 0; i < k.distortion.size(); ++i)
    require_finite(k.distortion[i], "calibration.distortion[" + std::to_string(i) + "]");
  require_finite(k.rms_px, "calibration.rms_px");
  require_finite(calibration.focal_setting_mm, "calibration.focal_setting_mm");

  WriteTransaction tx(db_, doing);
  {
    // The same calibration saved again (a second replay, a re-sync) is the
    // stored one, not a duplicate.
    Statement same(db_,
                   "SELECT id FROM calibration WHERE body_id IS ? AND width = ? AND height = ? "
                   "AND fx = ? AND fy = ? AND cx = ? AND cy = ? AND k1 = ? AND k2 = ? AND p1 = ? "
                   "AND p2 = ? AND k3 = ? AND rms_px = ? AND body = ? AND lens = ? AND focus = ? "
                   "AND focal_setting_mm = ? AND method = ? LIMIT 1",
                   doing);
    same.bind(1, calibration.body_id)
        .bind(2, k.width)
        .bind(3, k.height)
        .bind(4, k.fx)
        .bind(5, k.fy)
        .bind(6, k.cx)
        .bind(7, k.cy);
    for (int i = 0; i < 5; ++i) same.bind(8 + i, k.distortion[static_cast<std::size_t>(i)]);
    same.bind(13, k.rms_px)
        .bind(14, k.body)
        .bind(15, k.lens)
        .bind(16, k.focus)
        .bind(17, calibration.focal_setting_mm)
        .bind(18, calibration.method);
    if (same.step()) return same.column_int(0);
  }
  Statement st(db_,
               "INSERT INTO calibration (body_id, created_at, width, height, fx, fy, cx, cy, k1, "
               "k2, p1, p2, k3, rms_px, body, lens, focus, focal_setting_mm, method) VALUES "
               "(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
               doing);
  st.bind(1, calibration.body_id)
      .bind(2, or_now(calibration.created_at))
      .bind(3, k.width)
      .bind(4, k.height)
      .bind(5, k.fx)
      .bind(6, k.fy)
      .bind(7, k.cx)
      .bind(8, k.cy);
  for (int i = 0; i < 5; ++i) st.bind(9 + i, k.distortion[static_cast<std::size_t>(i)]);
  st.bind(14, k.rms_px)
      .bind(15, k.body)
      .bind(16, k.lens)
      .bind(17, k.focus)
      .bind(18, calibration.focal_setting_mm)
      .bind(19, calibration.method);
  st.run();
  const RecordId id = db_.last_insert_id();
  char detail[200];
  std::snprintf(detail, sizeof(detail), "calibration %lld: %dx%d fx %.1f fy %.1f rms %.3f px",
                static_cast<long long>(id), k.width, k.height, k.fx, k.fy, k.rms_px);
  insert_log(std::nullopt, "calibration saved", detail);
  tx.commit();
  return id;
}

namespace {
constexpr const char* kCalibrationColumns =
    "id, body_id, created_at, width, height, fx, fy, cx, cy, k1, k2, p1, p2, k3, rms_px, body, "
    "lens, focus, focal_setting_mm, method";

Calibration read_calibration(const Statement& st) {
  Calibration c;
  c.id = st.column_int(0);
  c.body_id = optional_id(st, 1);
  c.created_at = st.column_text(2);
  auto& k = c.intrinsics;
  k.width = static_cast<int>(st.column_int(3));
  k.height = static_cast<int>(st.column_int(4));
  k.fx = st.column_double(5);
  k.fy = st.column_double(6);
  k.cx = st.column_double(7);
  k.cy = st.column_double(8);
  for (int i = 0; i < 5; ++i) k.distortion[static_cast<std::size_t>(i)] = st.column_double(9 + i);
  k.rms_px = st.column_double(14);
  k.body = st.column_text(15);
  k.lens = st.column_text(16);
  k.focus = st.column_text(17);
  c.focal_setting_mm = st.column_double(18);
  c.method = st.column_text(19);
  return c;
}
}  // namespace

Calibration ProjectStore::load_calibration(RecordId id) {
  Statement st(db_, std::string("SELECT ") + kCalibrationColumns + " FROM calibration WHERE id = ?",
               "loading calibration " + std::to_string(id));
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no calibration " + std::to_string(id) + " in this project");
  return read_calibration(st);
}

std::vector<Calibration> ProjectStore::list_calibrations() {
  Statement st(db_, std::string("SELECT ") + kCalibrationColumns + " FROM calibration ORDER BY id",
               "listing calibrations");
  std::vector<Calibration> out;
  while (st.step()) out.push_back(read_calibration(st));
  return out;
}

// ---------------------------------------------------------------- captures

RecordId ProjectStore::store_image(const ImageBlob& image, const std::string& where) {
  if (image.bytes.empty()) throw InputError(where, "the image is empty");
  const std::string format = blobs::detect_image_format(image.bytes);
  if (format.empty()) throw InputError(where, "not a JPEG or PNG image");
  if (!image.format.empty() && image.format != format)
    throw InputError(where, "said to be " + image.format + " but the bytes are " + format);
  const std::string doing = "saving " + where;
  const auto size = static_cast<std::int64_t>(image.bytes.size());
  Statement find(
      db_, "SELECT id FROM image WHERE byte_size = ? AND format = ? AND bytes = ? LIMIT 1", doing);
  find.bind(1, size).bind(2, format).bind_blob(3, image.bytes);
  if (find.step()) return find.column_int(0);
  Statement st(db_, "INSERT INTO image (format, byte_size, bytes) VALUES (?, ?, ?)", doing);
  st.bind(1, format).bind(2, size).bind_blob(3, image.bytes);
  st.run();
  return db_.last_insert_id();
}

RecordId ProjectStore::save_capture(const Capture& capture) {
  const std::string doing = "saving capture '" + capture.label + "'";
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  {
    Statement visit(db_, "SELECT 1 FROM visit WHERE id = ?", doing);
    visit.bind(1, capture.visit_id);
    if (!visit.step())
      throw InputError("capture.visit_id",
                       "no visit " + std::to_string(capture.visit_id) + " in " + file_.string());
  }
  const RecordId left = store_image(capture.left, "capture '" + capture.label + "' left image");
  const RecordId right = store_image(capture.right, "capture '" + capture.label + "' right image");
  Statement st(db_,
               "INSERT INTO capture (visit_id, calibration_id, label, taken_at, created_at, "
               "left_image_id, right_image_id) VALUES (?, ?, ?, ?, ?, ?, ?)",
               doing);
  const std::string now = utc_now_iso8601();
  st.bind(1, capture.visit_id)
      .bind(2, capture.calibration_id)
      .bind(3, capture.label)
      .bind(4, capture.taken_at.empty() ? now : capture.taken_at)
      .bind(5, now)
      .bind(6, left)
      .bind(7, right);
  st.run();
  const RecordId id = db_.last_insert_id();
  Statement setting(db_, "INSERT INTO capture_setting (capture_id, key, value) VALUES (?, ?, ?)",
                    doing);
  for (const auto& [key, value] : capture.settings) {
    setting.reset();
    setting.bind(1, id).bind(2, key).bind(3, value);
    setting.run();
  }
  Statement exif(db_, "INSERT INTO capture_exif (capture_id, side, key, value) VALUES (?, ?, ?, ?)",
                 doing);
  for (const auto* side : {"left", "right"}) {
    const auto& entries = std::string(side) == "left" ? capture.left_exif : capture.right_exif;
    for (const auto& [key, value] : entries) {
      exif.reset();
      exif.bind(1, id).bind(2, side).bind(3, key).bind(4, value);
      exif.run();
    }
  }
  insert_log(capture.visit_id, "capture saved",
             "capture " + std::to_string(id) + " '" + capture.label + "': left " +
                 std::to_string(capture.left.bytes.size()) + " bytes, right " +
                 std::to_string(capture.right.bytes.size()) + " bytes");
  tx.commit();
  return id;
}

namespace {
constexpr const char* kCaptureSummarySelect =
    "SELECT c.id, c.visit_id, c.calibration_id, c.label, c.taken_at, l.format, l.byte_size, "
    "r.format, r.byte_size FROM capture c JOIN image l ON l.id = c.left_image_id "
    "JOIN image r ON r.id = c.right_image_id";

CaptureSummary read_capture_summary(const Statement& st) {
  CaptureSummary s;
  s.id = st.column_int(0);
  s.visit_id = st.column_int(1);
  s.calibration_id = optional_id(st, 2);
  s.label = st.column_text(3);
  s.taken_at = st.column_text(4);
  s.left_format = st.column_text(5);
  s.left_bytes = st.column_int(6);
  s.right_format = st.column_text(7);
  s.right_bytes = st.column_int(8);
  return s;
}
}  // namespace

Capture ProjectStore::load_capture(RecordId id) {
  const std::string doing = "loading capture " + std::to_string(id);
  ReadTransaction snapshot(db_);
  Statement st(db_,
               "SELECT c.id, c.visit_id, c.calibration_id, c.label, c.taken_at, l.format, "
               "l.bytes, r.format, r.bytes FROM capture c JOIN image l ON l.id = "
               "c.left_image_id JOIN image r ON r.id = c.right_image_id WHERE c.id = ?",
               doing);
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no capture " + std::to_string(id) + " in this project");
  Capture c;
  c.id = st.column_int(0);
  c.visit_id = st.column_int(1);
  c.calibration_id = optional_id(st, 2);
  c.label = st.column_text(3);
  c.taken_at = st.column_text(4);
  c.left.format = st.column_text(5);
  c.left.bytes = st.column_blob(6);
  c.right.format = st.column_text(7);
  c.right.bytes = st.column_blob(8);
  Statement settings(db_, "SELECT key, value FROM capture_setting WHERE capture_id = ?", doing);
  settings.bind(1, id);
  while (settings.step()) c.settings[settings.column_text(0)] = settings.column_text(1);
  Statement exif(db_, "SELECT side, key, value FROM capture_exif WHERE capture_id = ?", doing);
  exif.bind(1, id);
  while (exif.step())
    (exif.column_text(0) == "left" ? c.left_exif : c.right_exif)[exif.column_text(1)] =
        exif.column_text(2);
  return c;
}

ImageBlob ProjectStore::load_capture_image(RecordId capture_id, const std::string& side) {
  if (side != "left" && side != "right")
    throw InputError("capture image side", "must be 'left' or 'right', got '" + side + "'");
  Statement st(db_,
               "SELECT i.format, i.bytes FROM capture c JOIN image i ON i.id = c." + side +
                   "_image_id WHERE c.id = ?",
               "loading the " + side + " image of capture " + std::to_string(capture_id));
  st.bind(1, capture_id);
  if (!st.step())
    throw InputError(file_.string(),
                     "no capture " + std::to_string(capture_id) + " in this project");
  return {st.column_blob(1), st.column_text(0)};
}

std::vector<CaptureSummary> ProjectStore::list_captures(std::optional<RecordId> visit_id) {
  Statement st(
      db_,
      std::string(kCaptureSummarySelect) + " WHERE (?1 IS NULL OR c.visit_id = ?1) ORDER BY c.id",
      "listing captures");
  st.bind(1, visit_id);
  std::vector<CaptureSummary> out;
  while (st.step()) out.push_back(read_capture_summary(st));
  return out;
}

// ---------------------------------------------------------------- models

RecordId ProjectStore::save_model(const Model& model) {
  const std::string doing = "saving a model";
  require_writable(doing);
  const auto& r = model.registration;
  if (model.texture_capture_id && model.texture_side != "left" && model.texture_side != "right")
    throw InputError("model.texture_side", "must be 'left' or 'right' when a texture is given");
  if (!model.texture_capture_id && !model.texture_side.empty())
    throw InputError("model.texture_side", "given without a texture capture");
  if (!std::isfinite(r.scale) || r.scale <= 0)
    throw InputError("model.registration.scale", "must be a positive number");
  if (!r.rotation_wxyz.allFinite() || std::abs(r.rotation_wxyz.norm() - 1) > 1e-6)
    // 1e-6: a quaternion normalised in double precision is unit to ~1e-15;
    // anything further off was not normalised at all.
    throw InputError("model.registration.rotation", "must be a unit quaternion");
  require_finite(r.translation, "model.registration.translation");
  for (std::size_t i = 0; i < model.mesh.vertices.size(); ++i)
    if (!model.mesh.vertices[i].allFinite())
      throw InputError("model.mesh.vertices[" + std::to_string(i) + "]", "not finite");
  const std::vector<std::uint8_t> mesh = blobs::encode_mesh(model.mesh);

  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO model (capture_id, created_at, preset, vertex_count, face_count, "
               "mesh, texture_capture_id, texture_side, registration_kind, scale, qw, qx, qy, "
               "qz, tx, ty, tz, registration_parameters, registration_rms_m) VALUES (?, ?, ?, "
               "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
               doing);
  st.bind(1, model.capture_id)
      .bind(2, or_now(model.created_at))
      .bind(3, model.preset)
      .bind(4, static_cast<std::int64_t>(model.mesh.vertices.size()))
      .bind(5, static_cast<std::int64_t>(model.mesh.faces.size()))
      .bind_blob(6, mesh)
      .bind(7, model.texture_capture_id)
      .bind(8, model.texture_side)
      .bind(9, r.kind)
      .bind(10, r.scale);
  for (int i = 0; i < 4; ++i) st.bind(11 + i, r.rotation_wxyz[i]);
  for (int i = 0; i < 3; ++i) st.bind(15 + i, r.translation[i]);
  st.bind(18, r.parameters_json).bind(19, r.rms_m);
  st.run();
  const RecordId id = db_.last_insert_id();
  Statement res(db_,
                "INSERT INTO registration_residual (model_id, idx, label, dx, dy, dz) VALUES (?, "
                "?, ?, ?, ?, ?)",
                doing);
  for (std::size_t i = 0; i < model.residuals.size(); ++i) {
    const auto& e = model.residuals[i];
    require_finite(e.residual, "model.residuals[" + std::to_string(i) + "]");
    res.reset();
    res.bind(1, id)
        .bind(2, static_cast<std::int64_t>(i))
        .bind(3, e.label)
        .bind(4, e.residual.x())
        .bind(5, e.residual.y())
        .bind(6, e.residual.z());
    res.run();
  }
  insert_log(std::nullopt, "model saved",
             "model " + std::to_string(id) + ": " + std::to_string(model.mesh.vertices.size()) +
                 " vertices, " + std::to_string(model.mesh.faces.size()) + " faces, " +
                 (r.kind.empty() ? "unregistered" : r.kind));
  tx.commit();
  return id;
}

Model ProjectStore::load_model(RecordId id) {
  const std::string where = file_.string() + ": model " + std::to_string(id);
  ReadTransaction snapshot(db_);
  Statement st(db_,
               "SELECT id, capture_id, created_at, preset, mesh, texture_capture_id, "
               "texture_side, registration_kind, scale, qw, qx, qy, qz, tx, ty, tz, "
               "registration_parameters, registration_rms_m FROM model WHERE id = ?",
               "loading model " + std::to_string(id));
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no model " + std::to_string(id) + " in this project");
  Model m;
  m.id = st.column_int(0);
  m.capture_id = optional_id(st, 1);
  m.created_at = st.column_text(2);
  m.preset = st.column_text(3);
  m.mesh = blobs::decode_mesh(st.column_blob(4), where);
  m.texture_capture_id = optional_id(st, 5);
  m.texture_side = st.column_text(6);
  auto& r = m.registration;
  r.kind = st.column_text(7);
  r.scale = st.column_double(8);
  for (int i = 0; i < 4; ++i) r.rotation_wxyz[i] = st.column_double(9 + i);
  for (int i = 0; i < 3; ++i) r.translation[i] = st.column_double(13 + i);
  r.parameters_json = st.column_text(16);
  r.rms_m = st.column_double(17);
  Statement res(db_,
                "SELECT label, dx, dy, dz FROM registration_residual WHERE model_id = ? ORDER "
                "BY idx",
                "loading model " + std::to_string(id));
  res.bind(1, id);
  while (res.step())
    m.residuals.push_back(
        {res.column_text(0), {res.column_double(1), res.column_double(2), res.column_double(3)}});
  return m;
}

std::vector<ModelSummary> ProjectStore::list_models(std::optional<RecordId> capture_id) {
  Statement st(db_,
               "SELECT id, capture_id, preset, created_at, registration_kind, vertex_count, "
               "face_count, registration_rms_m FROM model WHERE (?1 IS NULL OR capture_id = ?1) "
               "ORDER BY id",
               "listing models");
  st.bind(1, capture_id);
  std::vector<ModelSummary> out;
  while (st.step()) {
    ModelSummary s;
    s.id = st.column_int(0);
    s.capture_id = optional_id(st, 1);
    s.preset = st.column_text(2);
    s.created_at = st.column_text(3);
    s.registration_kind = st.column_text(4);
    s.vertex_count = st.column_int(5);
    s.face_count = st.column_int(6);
    s.registration_rms_m = st.column_double(7);
    out.push_back(std::move(s));
  }
  return out;
}

// ---------------------------------------------------------------- measurements

std::vector<RecordId> ProjectStore::save_measurements(
    RecordId visit_id, const std::vector<Measurement>& measurements) {
  const std::string doing = "saving measurements";
  require_writable(doing);
  for (std::size_t i = 0; i < measurements.size(); ++i) {
    const auto& m = measurements[i];
    const std::string where = "measurements[" + std::to_string(i) + "] (" + m.label + ")";
    if (m.points.empty()) throw InputError(where, "has no points");
    for (const auto& p : m.points) require_finite(p, where + ".points");
    if (m.dip_deg.has_value() != m.dipdir_deg.has_value())
      throw InputError(where, "dip and dip direction must be given together");
    if (m.dip_deg) require_orientation(*m.dip_deg, *m.dipdir_deg, where);
    if (m.kind == Measurement::Kind::point_orientation && !m.dip_deg)
      throw InputError(where, "a point orientation needs its dip and dip direction");
    if (!m.rock_side.empty() && m.rock_side != "upper" && m.rock_side != "lower")
      throw InputError(where + ".rock_side", "must be 'upper' or 'lower'");
    if (!m.rock_side.empty() && m.kind != Measurement::Kind::area)
      throw InputError(where + ".rock_side", "only an area (a free face) has a rock side");
    require_finite(m.fit_rms_m, where + ".fit_rms_m");
  }
  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO measurement (visit_id, model_id, kind, label, joint_label, points, "
               "dip, dipdir, fit_rms_m, rock_side, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, "
               "?, ?, ?)",
               doing);
  std::vector<RecordId> ids;
  std::string labels;
  for (const auto& m : measurements) {
    const auto points = blobs::encode_points(m.points);
    st.reset();
    st.bind(1, visit_id)
        .bind(2, m.model_id)
        .bind(3, kind_text(m.kind))
        .bind(4, m.label)
        .bind(5, m.joint_label)
        .bind_blob(6, points)
        .bind(7, m.dip_deg)
        .bind(8, m.dipdir_deg)
        .bind(9, m.fit_rms_m)
        .bind(10, m.rock_side)
        .bind(11, or_now(m.created_at));
    st.run();
    ids.push_back(db_.last_insert_id());
    labels += (labels.empty() ? "" : " ") + m.label;
  }
  insert_log(visit_id, "measurements saved",
             std::to_string(measurements.size()) + " measurements: " + labels);
  tx.commit();
  return ids;
}

std::vector<Measurement> ProjectStore::list_measurements(std::optional<RecordId> visit_id) {
  Statement st(db_,
               "SELECT id, visit_id, model_id, kind, label, joint_label, points, dip, dipdir, "
               "fit_rms_m, rock_side, created_at FROM measurement WHERE (?1 IS NULL OR "
               "visit_id = ?1) ORDER BY id",
               "listing measurements");
  st.bind(1, visit_id);
  std::vector<Measurement> out;
  while (st.step()) {
    Measurement m;
    m.id = st.column_int(0);
    const std::string where = file_.string() + ": measurement " + std::to_string(m.id);
    m.visit_id = st.column_int(1);
    m.model_id = optional_id(st, 2);
    m.kind = kind_of(st.column_text(3), where);
    m.label = st.column_text(4);
    m.joint_label = st.column_text(5);
    m.points = blobs::decode_points(st.column_blob(6), where);
    m.dip_deg = st.column_optional_double(7);
    m.dipdir_deg = st.column_optional_double(8);
    m.fit_rms_m = st.column_double(9);
    m.rock_side = st.column_text(10);
    m.created_at = st.column_text(11);
    out.push_back(std::move(m));
  }
  return out;
}

// ---------------------------------------------------------------- joints

std::vector<RecordId> ProjectStore::save_joints(RecordId visit_id,
                                                const std::vector<JointSet>& sets,
                                                const std::vector<Joint>& joints) {
  const std::string doing = "saving joints";
  require_writable(doing);
  std::set<std::string> set_labels, joint_labels;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const std::string where = "joint_sets[" + std::to_string(i) + "] (" + sets[i].label + ")";
    if (sets[i].label.empty()) throw InputError(where, "has no label");
    if (!set_labels.insert(sets[i].label).second) throw InputError(where, "label is repeated");
    require_orientation(sets[i].dip_deg, sets[i].dipdir_deg, where);
    require_finite(sets[i].fisher_k, where + ".fisher_k");
  }
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const auto& j = joints[i];
    const std::string where = "joints[" + std::to_string(i) + "] (" + j.label + ")";
    if (j.label.empty()) throw InputError(where, "has no label");
    if (!joint_labels.insert(j.label).second) throw InputError(where, "label is repeated");
    require_orientation(j.dip_deg, j.dipdir_deg, where);
    if (j.point) require_finite(*j.point, where + ".point");
    if (j.friction_deg) require_finite(*j.friction_deg, where + ".friction");
    if (j.cohesion_pa) require_finite(*j.cohesion_pa, where + ".cohesion");
  }

  WriteTransaction tx(db_, doing);
  std::map<std::string, RecordId> set_ids;
  Statement set_st(db_,
                   "INSERT INTO joint_set (visit_id, label, dip, dipdir, fisher_k, count) "
                   "VALUES (?, ?, ?, ?, ?, ?)",
                   doing);
  for (const auto& s : sets) {
    set_st.reset();
    set_st.bind(1, visit_id)
        .bind(2, s.label)
        .bind(3, s.dip_deg)
        .bind(4, s.dipdir_deg)
        .bind(5, s.fisher_k)
        .bind(6, s.count);
    set_st.run();
    set_ids[s.label] = db_.last_insert_id();
  }
  Statement find_set(db_, "SELECT id FROM joint_set WHERE visit_id = ? AND label = ?", doing);
  Statement find_joint(db_, "SELECT 1 FROM joint WHERE visit_id = ? AND label = ?", doing);
  Statement st(db_,
               "INSERT INTO joint (visit_id, set_id, measurement_id, label, dip, dipdir, px, py, "
               "pz, friction_deg, cohesion_pa, source) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
               "?)",
               doing);
  std::vector<RecordId> ids;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const auto& j = joints[i];
    const std::string where = "joints[" + std::to_string(i) + "] (" + j.label + ")";
    find_joint.reset();
    find_joint.bind(1, visit_id).bind(2, j.label);
    if (find_joint.step())
      throw InputError(where, "visit " + std::to_string(visit_id) + " already has a joint " +
                                  j.label + "; nothing was saved");
    std::optional<RecordId> set_id;
    if (!j.set_label.empty()) {
      if (auto it = set_ids.find(j.set_label); it != set_ids.end()) {
        set_id = it->second;
      } else {
        find_set.reset();
        find_set.bind(1, visit_id).bind(2, j.set_label);
        if (!find_set.step())
          throw InputError(where + ".set", "no joint set '" + j.set_label + "' in visit " +
                                               std::to_string(visit_id) + "; nothing was saved");
        set_id = find_set.column_int(0);
      }
    }
    st.reset();
    st.bind(1, visit_id).bind(2, set_id).bind(3, j.measurement_id).bind(4, j.label);
    st.bind(5, j.dip_deg).bind(6, j.dipdir_deg);
    if (j.point) {
      st.bind(7, j.point->x()).bind(8, j.point->y()).bind(9, j.point->z());
    } else {
      st.bind_null(7).bind_null(8).bind_null(9);
    }
    st.bind(10, j.friction_deg).bind(11, j.cohesion_pa).bind(12, j.source);
    st.run();
    ids.push_back(db_.last_insert_id());
  }
  insert_log(visit_id, "joints saved",
             std::to_string(joints.size()) + " joints, " + std::to_string(sets.size()) + " sets");
  tx.commit();
  return ids;
}

std::vector<JointSet> ProjectStore::list_joint_sets(RecordId visit_id) {
  Statement st(db_,
               "SELECT id, label, dip, dipdir, fisher_k, count FROM joint_set WHERE visit_id = ? "
               "ORDER BY id",
               "listing joint sets");
  st.bind(1, visit_id);
  std::vector<JointSet> out;
  while (st.step()) {
    JointSet s;
    s.id = st.column_int(0);
    s.label = st.column_text(1);
    s.dip_deg = st.column_double(2);
    s.dipdir_deg = st.column_double(3);
    s.fisher_k = st.column_double(4);
    s.count = static_cast<int>(st.column_int(5));
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Joint> ProjectStore::list_joints(std::optional<RecordId> visit_id) {
  Statement st(db_,
               "SELECT j.id, j.visit_id, j.label, s.label, j.dip, j.dipdir, j.px, j.py, j.pz, "
               "j.friction_deg, j.cohesion_pa, j.measurement_id, j.source FROM joint j LEFT "
               "JOIN joint_set s ON s.id = j.set_id WHERE (?1 IS NULL OR j.visit_id = ?1) "
               "ORDER BY j.id",
               "listing joints");
  st.bind(1, visit_id);
  std::vector<Joint> out;
  while (st.step()) {
    Joint j;
    j.id = st.column_int(0);
    j.visit_id = st.column_int(1);
    j.label = st.column_text(2);
    j.set_label = st.column_text(3);
    j.dip_deg = st.column_double(4);
    j.dipdir_deg = st.column_double(5);
    if (!st.is_null(6))
      j.point = Eigen::Vector3d(st.column_double(6), st.column_double(7), st.column_double(8));
    j.friction_deg = st.column_optional_double(9);
    j.cohesion_pa = st.column_optional_double(10);
    j.measurement_id = optional_id(st, 11);
    j.source = st.column_text(12);
    out.push_back(std::move(j));
  }
  return out;
}

// ---------------------------------------------------------------- analyses

RecordId ProjectStore::save_analysis(const AnalysisRun& run) {
  const std::string doing = "saving a block analysis";
  require_writable(doing);
  for (std::size_t i = 0; i < run.blocks.size(); ++i) {
    const auto& b = run.blocks[i];
    const std::string where = "blocks[" + std::to_string(i) + "] (" + b.label + ")";
    require_finite(b.volume_m3, where + ".volume");
    if (b.fos && std::isnan(*b.fos)) throw InputError(where + ".fos", "is not a number");
  }
  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO analysis (visit_id, model_id, created_at, preset, effects, "
               "effects_json) VALUES (?, ?, ?, ?, ?, ?)",
               doing);
  st.bind(1, run.visit_id)
      .bind(2, run.model_id)
      .bind(3, or_now(run.created_at))
      .bind(4, run.preset)
      .bind(5, nlohmann::json(run.effects).dump())
      .bind(6, run.effects_json);
  st.run();
  const RecordId id = db_.last_insert_id();
  Statement block(db_,
                  "INSERT INTO block (analysis_id, label, source, code, volume_m3, finite, "
                  "removable, marginal, mode, fos, report_json) VALUES (?, ?, ?, ?, ?, ?, ?, ?, "
                  "?, ?, ?)",
                  doing);
  int removable = 0;
  for (const auto& b : run.blocks) {
    block.reset();
    block.bind(1, id)
        .bind(2, b.label)
        .bind(3, b.source)
        .bind(4, b.code)
        .bind(5, b.volume_m3)
        .bind(6, b.finite)
        .bind(7, b.removable)
        .bind(8, b.marginal)
        .bind(9, b.mode)
        .bind(10, b.fos)
        .bind(11, b.report_json);
    block.run();
    removable += b.removable ? 1 : 0;
  }
  insert_log(run.visit_id, "blocks analysed",
             "analysis " + std::to_string(id) + " (" + run.preset +
                 "): " + std::to_string(run.blocks.size()) + " blocks, " +
                 std::to_string(removable) + " removable");
  tx.commit();
  return id;
}

namespace {
AnalysisRun read_analysis(const Statement& st, const std::string& file) {
  AnalysisRun a;
  a.id = st.column_int(0);
  a.visit_id = st.column_int(1);
  a.model_id = optional_id(st, 2);
  a.created_at = st.column_text(3);
  a.preset = st.column_text(4);
  const std::string effects = st.column_text(5);
  auto parsed = nlohmann::json::parse(effects, nullptr, false);
  if (parsed.is_discarded() || !parsed.is_array())
    throw Error(file + ": analysis " + std::to_string(a.id) + ": stored effects are damaged");
  for (const auto& e : parsed) a.effects.push_back(e.is_string() ? e.get<std::string>() : e.dump());
  a.effects_json = st.column_text(6);
  return a;
}
constexpr const char* kAnalysisColumns =
    "id, visit_id, model_id, created_at, preset, effects, effects_json";
}  // namespace

AnalysisRun ProjectStore::load_analysis(RecordId id) {
  const std::string doing = "loading analysis " + std::to_string(id);
  ReadTransaction snapshot(db_);
  Statement st(db_, std::string("SELECT ") + kAnalysisColumns + " FROM analysis WHERE id = ?",
               doing);
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no analysis " + std::to_string(id) + " in this project");
  AnalysisRun a = read_analysis(st, file_.string());
  Statement blocks(db_,
                   "SELECT id, label, source, code, volume_m3, finite, removable, marginal, mode, "
                   "fos, report_json FROM block WHERE analysis_id = ? ORDER BY id",
                   doing);
  blocks.bind(1, id);
  while (blocks.step()) {
    BlockResult b;
    b.id = blocks.column_int(0);
    b.label = blocks.column_text(1);
    b.source = blocks.column_text(2);
    b.code = blocks.column_text(3);
    b.volume_m3 = blocks.column_double(4);
    b.finite = blocks.column_int(5) != 0;
    b.removable = blocks.column_int(6) != 0;
    b.marginal = blocks.column_int(7) != 0;
    b.mode = blocks.column_text(8);
    b.fos = blocks.column_optional_double(9);
    b.report_json = blocks.column_text(10);
    a.blocks.push_back(std::move(b));
  }
  return a;
}

std::vector<AnalysisRun> ProjectStore::list_analyses(std::optional<RecordId> visit_id) {
  Statement st(db_,
               std::string("SELECT ") + kAnalysisColumns +
                   " FROM analysis WHERE (?1 IS NULL OR visit_id = ?1) ORDER BY id",
               "listing analyses");
  st.bind(1, visit_id);
  std::vector<AnalysisRun> out;
  while (st.step()) out.push_back(read_analysis(st, file_.string()));
  return out;
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
  while (st.step())
    out.push_back({st.column_int(0), st.column_text(1), optional_id(st, 2), st.column_text(3),
                   st.column_text(4)});
  return out;
}

// ---------------------------------------------------------------- maintenance

IntegrityReport ProjectStore::check_integrity(OpenOptions::Check depth) {
  return run_check(db_, depth);
}

void ProjectStore::checkpoint() {
  if (read_only_) return;
  db_.exec("PRAGMA wal_checkpoint(TRUNCATE)", "writing the log into the project file");
}

}  // namespace rockface::storage
