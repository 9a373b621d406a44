// The geologist who mapped a visit (issue 46, schema 13): named when the
// visit begins and carried in its row's reading, renamed and taken away;
// a bad name or an unknown visit refused by name with nothing stored; a
// schema 12 project upgraded with its visits' geologist not recorded; the
// visit file's "geologist".
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "storage/project/visit_geologist.h"
#include "storage/scene/visit_file_json.h"
#include "tests/support/refusal.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

using rockface::test::refusal;

TEST(VisitGeologist, BegunWithTheVisitRenamedAndTakenAway) {
  TempDir dir("geologist");
  auto store = ProjectStore::create(dir / "g.rockface", test::sample_project());
  const RecordId mapped = store.begin_visit("tablet", "", "  Anna Berger ");
  const RecordId unnamed = store.begin_visit("tablet");
  // A name is text, whatever it holds: escaping is each page's own job.
  const RecordId quoted = store.begin_visit("replay card", "round 112", "O'Brien <b>");
  auto visits = store.list_visits();
  ASSERT_EQ(visits.size(), 3u);
  EXPECT_EQ(visits[0].geologist, std::optional<std::string>("Anna Berger")) << "trimmed";
  EXPECT_EQ(visits[1].geologist, std::nullopt);
  EXPECT_EQ(visits[2].geologist, std::optional<std::string>("O'Brien <b>"));
  EXPECT_EQ(visits[2].note, "round 112");

  store.save_visit_geologist(unnamed, "Jürg Müller");
  store.save_visit_geologist(mapped, "");
  EXPECT_EQ(store.load_visit_geologist(unnamed), std::optional<std::string>("Jürg Müller"));
  EXPECT_EQ(store.load_visit_geologist(mapped), std::nullopt);
  EXPECT_EQ(store.load_visit_geologist(quoted), std::optional<std::string>("O'Brien <b>"));
  visits = store.list_visits();
  EXPECT_EQ(visits[0].geologist, std::nullopt);
  EXPECT_EQ(visits[1].geologist, std::optional<std::string>("Jürg Müller"));
}

TEST(VisitGeologist, ABadNameOrAnUnknownVisitIsRefusedAndNothingStored) {
  TempDir dir("geologist-refused");
  auto store = ProjectStore::create(dir / "g.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("tablet", "", "Anna Berger");
  // 81 characters, one over; 80 accented ones (160 bytes) are fine.
  std::string accented;
  for (std::size_t i = 0; i < kGeologistMaxChars; ++i) accented += "é";
  for (const std::string& bad : {std::string(kGeologistMaxChars + 1, 'x'),
                                 std::string("Anna\nBerger"), std::string("not recorded")}) {
    const std::string said = refusal([&] { store.save_visit_geologist(visit, bad); });
    EXPECT_NE(said.find("visit " + std::to_string(visit) + " geologist"), std::string::npos)
        << "not named: " << said;
    EXPECT_EQ(store.load_visit_geologist(visit), std::optional<std::string>("Anna Berger")) << bad;
    // A visit begun with it is not begun at all.
    const std::string begun = refusal([&] { store.begin_visit("tablet", "", bad); });
    EXPECT_NE(begun.find("geologist"), std::string::npos) << begun;
    EXPECT_EQ(store.list_visits().size(), 1u) << bad;
  }
  store.save_visit_geologist(visit, accented);
  EXPECT_EQ(store.load_visit_geologist(visit), std::optional<std::string>(accented));
  const std::string unknown =
      refusal([&] { store.save_visit_geologist(visit + 7, "Anna Berger"); });
  EXPECT_NE(unknown.find("has no visit " + std::to_string(visit + 7)), std::string::npos)
      << unknown;
  EXPECT_EQ(store.load_visit_geologist(visit + 7), std::nullopt);
}

TEST(VisitGeologist, ASchema12ProjectIsUpgradedWithItsVisitsGeologistNotRecorded) {
  TempDir dir("geologist-migration");
  const auto file = dir / "twelve.rockface";
  {
    sqlite::Connection db = test::project_at_schema(file, 12);
    EXPECT_EQ(schema::version_of(db), 12);
  }
  auto store = ProjectStore::open(file);
  EXPECT_EQ(store.schema_version(), 13);
  const auto visits = store.list_visits();
  ASSERT_EQ(visits.size(), 1u);
  EXPECT_EQ(visits[0].geologist, std::nullopt);
  store.save_visit_geologist(1, "Anna Berger");
  EXPECT_EQ(store.load_visit_geologist(1), std::optional<std::string>("Anna Berger"));
}

TEST(VisitGeologist, TheVisitFileNamesIt) {
  const VisitFile v = parse_visit_file(
      R"({"format": "rockface-visit/1", "geologist": " Anna Berger ", "note": "round 112"})",
      "/cards/visit.json");
  EXPECT_EQ(v.geologist, "Anna Berger");
  EXPECT_EQ(v.note, "round 112");
  const std::string said = refusal([] {
    parse_visit_file(R"({"format": "rockface-visit/1", "geologist": "a\tb"})", "/cards/visit.json");
  });
  EXPECT_NE(said.find("geologist"), std::string::npos) << said;
  EXPECT_NE(said.find("visit.json"), std::string::npos) << said;
}

}  // namespace
}  // namespace rockface::storage
