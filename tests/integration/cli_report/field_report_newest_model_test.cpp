// The field report of a pair whose 3D image was stored again (issue 42):
// north given after the reconstruction (the tablet's compass line,
// `rockface orient`) stores the visit's models turned anew, and the report
// reads the newest, not the first, which nothing had oriented: a visit
// oriented on the tablet was reported "north: none".
#include <gtest/gtest.h>

#include "storage/field_report/field_report.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace {

using namespace rockface::storage;

TEST(FieldReportNewestModel, APairStoredAgainIsReportedAsItsNewestModel) {
  test::TempDir dir("field-report-newest-model");
  ProjectStore store = ProjectStore::create(dir / "site.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("tablet");
  const RecordId capture = store.save_capture(test::sample_capture(visit, 1));
  Model first = test::sample_model(capture);
  first.registration.kind = "range_pole";
  first.registration.scale = 0.5;
  first.preset = "fast";
  store.save_model(first);
  Model turned = test::sample_model(capture);
  turned.registration.translation = {7.0, 8.0, 9.0};
  store.save_model(turned);

  const FieldReport r = collect_field_report(store, visit);
  // The turned model's registration, exactly as stored (no arithmetic on
  // the way but the quaternion's rotation, which the scale and the
  // translation do not pass through).
  EXPECT_EQ(r.model_scale, turned.registration.scale);
  EXPECT_EQ(r.model_translation, turned.registration.translation);
  EXPECT_EQ(r.preset, "standard");
}

}  // namespace
