// Where a trace came from (schema step 8, issue 25): "hand", "proposed" or
// "corrected", stored and read back; a project of schema 7 is upgraded with
// every earlier trace marked "hand"; anything else is refused by name and
// nothing stored.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/project/project_blobs.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

TEST(ProjectTraceOrigin, EachOriginRoundTrips) {
  TempDir dir("origin");
  auto store = ProjectStore::create(dir / "o.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("test");
  auto ms = test::sample_measurements(std::nullopt);
  ms[0].origin = "proposed";
  ms[1].origin = "corrected";  // ms[2], ms[3]: an area and a point, by hand
  store.save_measurements(visit, ms);
  const auto back = store.list_measurements(visit);
  ASSERT_EQ(back.size(), ms.size());
  EXPECT_EQ(back[0].origin, "proposed");
  EXPECT_EQ(back[1].origin, "corrected");
  EXPECT_EQ(back[2].origin, "hand");
  EXPECT_EQ(back[3].origin, "hand");
}

TEST(ProjectTraceOrigin, AnUnknownOriginOrAProposedAreaIsRefusedAndNothingStored) {
  TempDir dir("origin-bad");
  auto store = ProjectStore::create(dir / "o.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("test");
  auto ms = test::sample_measurements(std::nullopt);
  ms[1].origin = "guessed";
  try {
    store.save_measurements(visit, ms);
    FAIL() << "origin 'guessed' stored";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "measurements[1] (T2).origin");
  }
  ms[1].origin = "hand";
  ms[2].origin = "proposed";  // an area
  EXPECT_THROW(store.save_measurements(visit, ms), InputError);
  EXPECT_TRUE(store.list_measurements(visit).empty());
}

TEST(ProjectTraceOrigin, ASchema7ProjectIsUpgradedWithItsTracesByHand) {
  TempDir dir("origin-migration");
  const auto file = dir / "seven.rockface";
  {
    sqlite::Connection db = test::project_at_schema(file, 7);
    sqlite::Statement st(db,
                         "INSERT INTO measurement (visit_id, kind, label, joint_label, points, "
                         "fit_rms_m, rock_side, created_at) VALUES (1, 'trace', 'T1', '', ?, 0, "
                         "'', '2026-01-02T09:00:00.000Z')",
                         "test");
    const auto blob = blobs::encode_points({{0, 0, 0}, {1, 0, 1}});
    st.bind_blob(1, blob);
    st.run();
    EXPECT_EQ(schema::version_of(db), 7);
  }
  auto store = ProjectStore::open(file);
  EXPECT_GE(store.schema_version(), 8);  // and on to the current one
  const auto back = store.list_measurements(1);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].origin, "hand");
  EXPECT_TRUE(store.check_integrity().ok);
}

}  // namespace
}  // namespace rockface::storage
