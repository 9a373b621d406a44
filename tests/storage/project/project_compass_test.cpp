// A trace's compass reading (schema step 9, issue 27): stored with the
// trace's measurement and read back; replaced in place on the tablet (the
// trace keeps its id); a project of schema 8 is upgraded keeping its rows,
// with no reading on its traces; a reading on an area, or one half given,
// is refused by name and nothing stored.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "storage/project/project_blobs.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

TEST(ProjectCompass, AReadingRoundTripsAndIsReplacedInPlace) {
  TempDir dir("compass");
  auto store = ProjectStore::create(dir / "c.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("test");
  auto ms = test::sample_measurements(std::nullopt);
  ms[1].compass_dip_deg = 74.5;
  ms[1].compass_dipdir_deg = 111;
  ms[1].compass_off_deg = 2.25;
  const auto ids = store.save_measurements(visit, ms);
  auto back = store.list_measurements(visit);
  ASSERT_EQ(back.size(), ms.size());
  EXPECT_FALSE(back[0].compass_dip_deg);
  EXPECT_EQ(back[1].compass_dip_deg, 74.5);
  EXPECT_EQ(back[1].compass_dipdir_deg, 111);
  EXPECT_EQ(back[1].compass_off_deg, 2.25);

  Measurement again = back[0];
  again.dip_deg = 60;
  again.dipdir_deg = 200;
  again.sigma_deg = 2;
  again.note = "orientation from a compass reading";
  again.compass_dip_deg = 60;
  again.compass_dipdir_deg = 200;
  again.compass_off_deg = 1.5;
  store.set_trace_plane(ids[0], again);
  back = store.list_measurements(visit);
  EXPECT_EQ(back[0].id, ids[0]);
  EXPECT_EQ(back[0].dip_deg, 60);
  EXPECT_EQ(back[0].compass_dipdir_deg, 200);
  EXPECT_EQ(back[0].note, "orientation from a compass reading");
  EXPECT_EQ(back[0].points, ms[0].points) << "the trace itself stays";
  // Cleared: the reading goes.
  again.compass_dip_deg.reset();
  again.compass_dipdir_deg.reset();
  again.compass_off_deg.reset();
  store.set_trace_plane(ids[0], again);
  EXPECT_FALSE(store.list_measurements(visit)[0].compass_dip_deg);
  EXPECT_THROW(store.set_trace_plane(ids[2], again), InputError) << "an area is no trace";
}

TEST(ProjectCompass, AReadingOnAnAreaOrHalfGivenIsRefusedAndNothingStored) {
  TempDir dir("compass-bad");
  auto store = ProjectStore::create(dir / "c.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("test");
  auto ms = test::sample_measurements(std::nullopt);
  ms[2].compass_dip_deg = 30;  // an area
  ms[2].compass_dipdir_deg = 30;
  try {
    store.save_measurements(visit, ms);
    FAIL() << "a reading on an area stored";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "measurements[2] (" + ms[2].label + ").compass");
  }
  ms[2].compass_dip_deg.reset();
  ms[2].compass_dipdir_deg.reset();
  ms[0].compass_dip_deg = 30;  // no dip direction
  EXPECT_THROW(store.save_measurements(visit, ms), InputError);
  ms[0].compass_dipdir_deg = 30;
  ms[0].compass_dip_deg = 91;
  try {
    store.save_measurements(visit, ms);
    FAIL() << "dip 91 stored";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "measurements[0] (" + ms[0].label + ").compass.dip");
  }
  EXPECT_TRUE(store.list_measurements(visit).empty());
}

TEST(ProjectCompass, ASchema8ProjectIsUpgradedKeepingItsRows) {
  TempDir dir("compass-migration");
  const auto file = dir / "eight.rockface";
  {
    sqlite::Connection db = test::project_at_schema(file, 8);
    sqlite::Statement st(db,
                         "INSERT INTO measurement (visit_id, kind, label, joint_label, points, "
                         "dip, dipdir, fit_rms_m, rock_side, created_at, note, origin) VALUES (1, "
                         "'trace', 'T1', 'J1', ?, 40, 60, 0.002, '', '2026-01-02T09:00:00.000Z', "
                         "'fitted', 'proposed')",
                         "test");
    const auto blob = blobs::encode_points({{0, 0, 0}, {1, 0, 1}, {2, 1, 1}});
    st.bind_blob(1, blob);
    st.run();
    EXPECT_EQ(schema::version_of(db), 8);
  }
  auto store = ProjectStore::open(file);
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  const auto back = store.list_measurements(1);
  ASSERT_EQ(back.size(), 1u);
  // Every value of the row as it was, and no reading.
  EXPECT_EQ(back[0].label, "T1");
  EXPECT_EQ(back[0].joint_label, "J1");
  EXPECT_EQ(back[0].points.size(), 3u);
  EXPECT_EQ(back[0].dip_deg, 40);
  EXPECT_EQ(back[0].dipdir_deg, 60);
  EXPECT_EQ(back[0].fit_rms_m, 0.002);
  EXPECT_EQ(back[0].note, "fitted");
  EXPECT_EQ(back[0].origin, "proposed");
  EXPECT_FALSE(back[0].compass_dip_deg);
  EXPECT_FALSE(back[0].compass_dipdir_deg);
  EXPECT_FALSE(back[0].compass_off_deg);
  EXPECT_TRUE(store.check_integrity().ok);
}

}  // namespace
}  // namespace rockface::storage
