// Project schema 6: the rows of an older project get a UUID in the upgrade,
// each different and a version-4 UUID; a record made afterwards gets one
// when it is created (so tablets never collide on the office server).
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "storage/office/sqlite_rows.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::office_test {
namespace {

using namespace storage;

std::vector<std::string> uuids(sqlite::Connection& db, const std::string& table) {
  office::RawStatement st(db, "SELECT uuid FROM " + table + " ORDER BY rowid", "reading uuids");
  std::vector<std::string> out;
  while (st.step()) out.push_back(st.type(0) == SQLITE_NULL ? "" : st.text(0));
  return out;
}

TEST(ProjectUuids, AnOlderProjectsRowsGetUuidsAndNewRecordsGetThemAtCreation) {
  test::TempDir dir("office-uuid-migration");
  const auto file = dir / "old.rockface";
  {
    sqlite::Connection db(file, sqlite::Connection::Access::read_write_create);
    schema::create_version_1(db);
    schema::migrate_to(db, 5);
    db.exec(
        "INSERT INTO project (id, name, datum_x, datum_y, datum_z, created_at, created_by) "
        "VALUES (1, 'old', 0, 0, 0, '2025-01-01T00:00:00.000Z', 'rockface 0.1');"
        "INSERT INTO visit (started_at, source) VALUES ('2025-01-01T08:00:00.000Z', 'tablet');"
        "INSERT INTO visit (started_at, source) VALUES ('2025-01-02T08:00:00.000Z', 'tablet');"
        "INSERT INTO action_log (at, visit_id, action, detail) VALUES "
        "('2025-01-01T08:00:00.000Z', 1, 'visit started', 'tablet');",
        "writing a schema-5 project");
  }
  ProjectStore store = ProjectStore::open(file);
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  store.begin_visit("tablet");
  store.checkpoint();
  sqlite::Connection db(file, sqlite::Connection::Access::read_only);
  const std::regex v4("[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}");
  std::set<std::string> seen;
  for (const char* table : {"project", "visit", "action_log"}) {
    for (const auto& u : uuids(db, table)) {
      EXPECT_TRUE(std::regex_match(u, v4)) << table << ": '" << u << "'";
      EXPECT_TRUE(seen.insert(u).second) << "the same UUID twice: " << u;
    }
  }
  EXPECT_EQ(uuids(db, "visit").size(), 3u) << "two old visits and a new one";
}

}  // namespace
}  // namespace rockface::office_test
