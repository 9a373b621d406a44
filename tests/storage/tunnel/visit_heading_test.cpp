// The heading a visit was taken at (issue 46, schema 12): named, renamed
// and taken away; a bad name or an unknown visit refused by name with
// nothing stored; a schema 11 project upgraded with its visits unnamed; the
// visit file's "heading".
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "storage/scene/visit_file_json.h"
#include "storage/tunnel/visit_heading.h"
#include "tests/support/refusal.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

using rockface::test::refusal;

TEST(VisitHeading, IsNamedRenamedAndTakenAway) {
  TempDir dir("heading");
  auto store = ProjectStore::create(dir / "h.rockface", test::sample_project());
  const RecordId north = store.begin_visit("north face");
  const RecordId south = store.begin_visit("south face");
  const RecordId unnamed = store.begin_visit("one face");
  EXPECT_EQ(load_visit_heading(store, north), "");
  save_visit_heading(store, north, "  North portal ");
  save_visit_heading(store, south, "Südportal");
  EXPECT_EQ(load_visit_heading(store, north), "North portal") << "trimmed";
  EXPECT_EQ(load_visit_heading(store, south), "Südportal");
  EXPECT_EQ(load_visit_heading(store, unnamed), "");
  save_visit_heading(store, north, "Bench");
  EXPECT_EQ(load_visit_heading(store, north), "Bench");
  save_visit_heading(store, south, "");
  const auto all = list_visit_headings(store);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all.at(north), "Bench");
}

TEST(VisitHeading, ABadNameOrAnUnknownVisitIsRefusedAndNothingStored) {
  TempDir dir("heading-refused");
  auto store = ProjectStore::create(dir / "h.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("face");
  save_visit_heading(store, visit, "North portal");
  // 41 characters, one over; 40 accented ones (80 bytes) are fine.
  const std::string long_name(41, 'x');
  std::string accented;
  for (int i = 0; i < 40; ++i) accented += "é";
  for (const std::string& bad : {long_name, std::string("North\nportal"), std::string("—")}) {
    const std::string said = refusal([&] { save_visit_heading(store, visit, bad); });
    EXPECT_NE(said.find("visit " + std::to_string(visit) + " heading"), std::string::npos)
        << "not named: " << said;
    EXPECT_EQ(load_visit_heading(store, visit), "North portal") << bad;
  }
  save_visit_heading(store, visit, accented);
  EXPECT_EQ(load_visit_heading(store, visit), accented);
  const std::string unknown = refusal([&] { save_visit_heading(store, visit + 7, "Bench"); });
  EXPECT_NE(unknown.find("has no visit " + std::to_string(visit + 7)), std::string::npos)
      << unknown;
  EXPECT_EQ(list_visit_headings(store).size(), 1u);
}

TEST(VisitHeading, ASchema11ProjectIsUpgradedWithItsVisitsUnnamed) {
  TempDir dir("heading-migration");
  const auto file = dir / "eleven.rockface";
  {
    sqlite::Connection db = test::project_at_schema(file, 11);
    EXPECT_EQ(schema::version_of(db), 11);
  }
  auto store = ProjectStore::open(file);
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  EXPECT_EQ(load_visit_heading(store, 1), "");
  save_visit_heading(store, 1, "Top heading");
  EXPECT_EQ(load_visit_heading(store, 1), "Top heading");
}

TEST(VisitHeading, TheVisitFileNamesIt) {
  const VisitFile v = parse_visit_file(
      R"({"format": "rockface-visit/1", "heading": " South portal ", "note": "round 112"})",
      "/cards/visit.json");
  EXPECT_EQ(v.heading, "South portal");
  EXPECT_EQ(v.note, "round 112");
  const std::string said = refusal([] {
    parse_visit_file(R"({"format": "rockface-visit/1", "heading": "a\tb"})", "/cards/visit.json");
  });
  EXPECT_NE(said.find("heading"), std::string::npos) << said;
  EXPECT_NE(said.find("visit.json"), std::string::npos) << said;
}

}  // namespace
}  // namespace rockface::storage
