// Issue 42: a model records exactly what scaled, levelled and oriented it,
// and every reader takes that record. Issue 37: the stored parameters are
// read once (storage::read_model_registration), not by each screen.
//
// The parameters here are written by the reconstruction report's own writer
// (storage::reconstruction_report_json) from a reconstruction result stated
// by hand: what a pole-only pair, a pole-and-compass pair and a pair on
// control points record.
#include <gtest/gtest.h>

#include "storage/project/model_registration.h"
#include "storage/project/project_store.h"
#include "storage/report/reconstruction_report.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

photogrammetry::ReconstructionResult pole_pair(bool compass) {
  photogrammetry::ReconstructionResult r;
  r.scaled = true;
  r.scale_source = "range pole";
  r.vertical_source = "range pole";
  r.north_source = compass ? "compass" : "none";
  r.distance = 9.5;
  r.base = 1.8;
  photogrammetry::RangePoleTargets t;
  t.left[0].centre_px = Eigen::Vector2d(700, 620);
  t.left[1].centre_px = Eigen::Vector2d(702, 410);
  t.model = {Eigen::Vector3d(0, 0, 5), Eigen::Vector3d(0, -0.4, 5)};
  r.targets = t;
  if (compass) r.north_rotation_deg = 12.5;
  return r;
}

Registration stored(const photogrammetry::ReconstructionResult& rec, const std::string& kind,
                    bool compass) {
  ReconstructionReportContext c;
  c.preset = "fast";
  c.range_pole_m = 2.0;
  if (compass) {
    photogrammetry::NorthReference n;
    n.from_px = {100, 500};
    n.to_px = {1400, 520};
    n.azimuth_deg = 88.0;
    c.north = n;
  }
  Registration r;
  r.kind = kind;
  r.parameters_json = reconstruction_report_json(rec, c);
  return r;
}

TEST(ModelRegistration, KindSaysWhatScaledAndOrientedTheModel) {
  EXPECT_EQ(registration_kind("range pole", "compass"), "range_pole_compass");
  EXPECT_EQ(registration_kind("range pole", "none"), "range_pole");
  EXPECT_EQ(registration_kind("control points", "control points"), "ground_control");
  EXPECT_EQ(registration_kind("baseline", "none"), "baseline");
  EXPECT_EQ(registration_kind("none", "none"), "none");
}

TEST(ModelRegistration, PoleWithoutCompassIsScaledAndLevelledButHasNoNorth) {
  // As every pole-scaled model was stored before issue 42: kind
  // "range_pole_compass" whatever gave north.
  const ModelRegistration r =
      read_model_registration(stored(pole_pair(false), "range_pole_compass", false));
  EXPECT_EQ(r.kind, "range_pole");
  EXPECT_EQ(r.record, ModelRegistration::Record::reconstruction);
  EXPECT_FALSE(r.oriented());
  EXPECT_TRUE(r.is_scaled());
  EXPECT_FALSE(r.has_north);
  EXPECT_EQ(r.scale_source, "range pole");
  EXPECT_EQ(r.vertical_source, "range pole");
  ASSERT_TRUE(r.pole_length_m);
  EXPECT_EQ(*r.pole_length_m, 2.0);
  ASSERT_EQ(r.pole_targets.size(), 2u);
  EXPECT_EQ(r.pole_targets[0].which, "lower");
  EXPECT_EQ(r.pole_targets[0].left_px, Eigen::Vector2d(700, 620));
  ASSERT_TRUE(r.distance_m);
  EXPECT_EQ(*r.distance_m, 9.5);
}

TEST(ModelRegistration, PoleWithCompassIsOrientedAndKeepsTheLine) {
  const ModelRegistration r =
      read_model_registration(stored(pole_pair(true), "range_pole_compass", true));
  EXPECT_EQ(r.kind, "range_pole_compass");
  EXPECT_TRUE(r.oriented());
  EXPECT_TRUE(r.has_north);
  ASSERT_TRUE(r.compass_azimuth_deg);
  EXPECT_EQ(*r.compass_azimuth_deg, 88.0);
  ASSERT_TRUE(r.north_rotation_deg);
  EXPECT_EQ(*r.north_rotation_deg, 12.5);
}

TEST(ModelRegistration, MalformedOrEmptyParametersGiveTheKindAlone) {
  for (const std::string text : {"", "{", "[1, 2]", "null", R"({"registration": 7})"}) {
    Registration reg;
    reg.kind = "range_pole_compass";
    reg.parameters_json = text;
    const ModelRegistration r = read_model_registration(reg);
    EXPECT_EQ(r.kind, "range_pole_compass") << text;
    EXPECT_TRUE(r.scale_source.empty()) << text;
    EXPECT_TRUE(r.pole_targets.empty()) << text;
    // A record that does not say what gave north keeps its kind's word.
    EXPECT_TRUE(r.oriented()) << text;
  }
  Registration none;
  none.kind = "none";
  EXPECT_FALSE(read_model_registration(none).oriented());
  EXPECT_FALSE(read_model_registration(none).is_scaled());
}

// A project written before issue 42 reads honestly: the listing (which the
// Project screen and the placement take) and the loaded model agree with
// what the stored report says, without a migration of the file.
TEST(ModelRegistration, StoredKindsAreReadHonestly) {
  test::TempDir dir("model-registration");
  auto store = ProjectStore::create(dir / "site.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("tablet", "");
  const RecordId capture = store.save_capture(test::sample_capture(visit, 1));
  Model pole_only = test::sample_model(capture);
  pole_only.registration = stored(pole_pair(false), "range_pole_compass", false);
  const RecordId a = store.save_model(pole_only);
  Model with_compass = test::sample_model(capture);
  with_compass.registration = stored(pole_pair(true), "range_pole_compass", true);
  const RecordId b = store.save_model(with_compass);
  Model control = test::sample_model(capture);
  control.registration.kind = "control points";  // as `--gcp` recorded it
  const RecordId c = store.save_model(control);

  EXPECT_EQ(store.load_model(a).registration.kind, "range_pole");
  EXPECT_EQ(store.load_model(b).registration.kind, "range_pole_compass");
  EXPECT_EQ(store.load_model(c).registration.kind, "ground_control");
  const auto listed = store.list_models(capture);
  ASSERT_EQ(listed.size(), 3u);
  EXPECT_EQ(listed[0].registration_kind, "range_pole");
  EXPECT_EQ(listed[1].registration_kind, "range_pole_compass");
  EXPECT_EQ(listed[2].registration_kind, "ground_control");
}

}  // namespace
}  // namespace rockface::storage
