#include "storage/project/project_integrity.h"

#include <sqlite3.h>

#include <string>
#include <vector>

#include "core/common/error.h"

namespace rockface::storage {

namespace {

using sqlite::Connection;
using sqlite::Statement;

// The tables whose rows are the file's bulk (schema 11: photographs, 3D
// images in 8 MiB parts, blobs of the office's sync).
constexpr const char* kBulkTables = "'image', 'model_mesh_part', 'sync_blob'";

std::uint32_t big_endian_u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) |
         (std::uint32_t{b[at + 2]} << 8) | std::uint32_t{b[at + 3]};
}

// The header's page count is valid when its "version valid for" equals the
// change counter (https://sqlite.org/fileformat.html, 1.3.7); the file is
// never shorter than that (WAL mode writes pages past it, never cuts it).
void check_length(Connection& db, IntegrityReport& report) {
  const std::vector<std::uint8_t> header = db.read_start(100);
  if (header.size() < 100) {
    report.problems.push_back("the file is shorter than its header");
    return;
  }
  if (big_endian_u32(header, 92) != big_endian_u32(header, 24)) return;
  const std::uint32_t page_size_field = (std::uint32_t{header[16]} << 8) | header[17];
  const std::int64_t page_size = page_size_field == 1 ? 65536 : page_size_field;
  const std::int64_t expected = page_size * big_endian_u32(header, 28);
  const std::int64_t size = db.size_on_disk();
  if (size < expected)
    report.problems.push_back("the file is cut short: " + std::to_string(size) + " of " +
                              std::to_string(expected) + " bytes");
}

void run_pragma(Connection& db, const std::string& pragma, IntegrityReport& report) {
  Statement st(db, pragma, "checking the project's integrity");
  while (st.step()) {
    const std::string line = st.column_text(0);
    if (line != "ok") report.problems.push_back(line);
  }
}

int stop_when_cancelled(void* flag) {
  return static_cast<const std::atomic<bool>*>(flag)->load() ? 1 : 0;
}

}  // namespace

IntegrityReport check_project_pages(Connection& db, IntegrityDepth depth,
                                    const std::atomic<bool>* cancel) {
  IntegrityReport report;
  if (cancel && cancel->load()) return report;
  if (cancel)
    sqlite3_progress_handler(db.handle(), 1000, stop_when_cancelled,
                             const_cast<std::atomic<bool>*>(cancel));
  try {
    switch (depth) {
      case IntegrityDepth::full:
        run_pragma(db, "PRAGMA integrity_check(20)", report);
        break;
      case IntegrityDepth::quick:
        run_pragma(db, "PRAGMA quick_check(20)", report);
        break;
      case IntegrityDepth::rows: {
        // A file cut short says so, before its missing pages make a table's
        // check fail with SQLite's "malformed".
        check_length(db, report);
        if (!report.problems.empty()) break;
        std::vector<std::string> tables;
        Statement st(db,
                     std::string("SELECT name FROM sqlite_schema WHERE type = 'table' AND name "
                                 "NOT IN (") +
                         kBulkTables + ") ORDER BY name",
                     "checking the project's integrity");
        while (st.step()) tables.push_back(st.column_text(0));
        for (const auto& t : tables) run_pragma(db, "PRAGMA quick_check(\"" + t + "\")", report);
        break;
      }
    }
  } catch (...) {
    if (cancel) sqlite3_progress_handler(db.handle(), 0, nullptr, nullptr);
    if (cancel && cancel->load()) return {};  // stopped: neither ok nor damaged
    throw;
  }
  if (cancel) sqlite3_progress_handler(db.handle(), 0, nullptr, nullptr);
  if (report.problems.size() > 20) report.problems.resize(20);
  report.ok = report.problems.empty();
  return report;
}

IntegrityReport check_project_file(const std::filesystem::path& file, IntegrityDepth depth,
                                   const std::atomic<bool>* cancel) {
  Connection db(file, Connection::Access::read_only);
  sqlite3_busy_timeout(db.handle(), 30000);
  try {
    return check_project_pages(db, depth, cancel);
  } catch (const InputError& e) {
    // SQLite refused a page outright (SQLITE_CORRUPT): that is the finding.
    IntegrityReport report;
    report.problems.push_back(e.reason());
    return report;
  }
}

}  // namespace rockface::storage
