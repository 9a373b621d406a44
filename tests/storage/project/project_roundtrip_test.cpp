// Every kind of record goes into a project file and comes back unchanged
// after the store is closed and the file reopened.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

// Stored values are IEEE doubles written and read without conversion, so
// round trips are compared exactly (EXPECT_EQ), not within a tolerance.
void expect_same(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  EXPECT_EQ(a.x(), b.x());
  EXPECT_EQ(a.y(), b.y());
  EXPECT_EQ(a.z(), b.z());
}

TEST(ProjectRoundTrip, EveryKindOfRecordSurvivesReopening) {
  TempDir dir("roundtrip");
  const auto file = dir / "site.rockface";
  const ProjectInfo info = test::sample_project();
  const Calibration calibration = test::sample_calibration();
  Capture capture;
  Model model;
  std::vector<Measurement> measurements;
  AnalysisRun analysis;
  RecordId visit = 0, body_id = 0, calibration_id = 0, capture_id = 0, model_id = 0,
           analysis_id = 0;
  std::vector<RecordId> measurement_ids, joint_ids;
  {
    auto store = ProjectStore::create(file, info);
    EXPECT_FALSE(store.read_only());
    visit = store.begin_visit("tablet", "first day at the face");
    body_id = store.save_camera_body({0, "Nikon", "D7500", "3012345"});
    EXPECT_EQ(store.save_camera_body({0, "Nikon", "D7500", "3012345"}), body_id)
        << "the same body is found again, not duplicated";
    Calibration c = calibration;
    c.body_id = body_id;
    calibration_id = store.save_calibration(c);
    EXPECT_EQ(store.save_calibration(c), calibration_id) << "same calibration, not a copy";
    Calibration other = c;
    other.intrinsics.fx += 0.5;
    const RecordId recalibrated = store.save_calibration(other);
    EXPECT_NE(recalibrated, calibration_id);
    capture = test::sample_capture(visit, 1);
    capture.calibration_id = calibration_id;
    capture_id = store.save_capture(capture);
    model = test::sample_model(capture_id);
    model_id = store.save_model(model);
    measurements = test::sample_measurements(model_id);
    measurement_ids = store.save_measurements(visit, measurements);
    auto joints = test::sample_joints();
    joints[0].measurement_id = measurement_ids[0];
    joint_ids = store.save_joints(visit, test::sample_joint_sets(), joints);
    analysis = test::sample_analysis(visit, model_id);
    analysis_id = store.save_analysis(analysis);
    store.log_action(visit, "export csv", "joints.csv");
  }

  auto store = ProjectStore::open(file);
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  const ProjectInfo p = store.project();
  EXPECT_EQ(p.name, info.name);
  expect_same(p.datum, info.datum);
  EXPECT_EQ(p.datum_crs, info.datum_crs);
  EXPECT_FALSE(p.created_at.empty());
  EXPECT_FALSE(p.created_by.empty());

  const auto visits = store.list_visits();
  ASSERT_EQ(visits.size(), 1u);
  EXPECT_EQ(visits[0].id, visit);
  EXPECT_EQ(visits[0].source, "tablet");
  EXPECT_EQ(visits[0].note, "first day at the face");
  EXPECT_EQ(store.latest_visit(), visit);

  const auto bodies = store.list_camera_bodies();
  ASSERT_EQ(bodies.size(), 1u);
  EXPECT_EQ(bodies[0].serial, "3012345");

  const Calibration c = store.load_calibration(calibration_id);
  EXPECT_EQ(c.body_id, body_id);
  EXPECT_EQ(c.intrinsics.width, 6000);
  EXPECT_EQ(c.intrinsics.height, 4000);
  EXPECT_EQ(c.intrinsics.fx, calibration.intrinsics.fx);
  EXPECT_EQ(c.intrinsics.fy, calibration.intrinsics.fy);
  EXPECT_EQ(c.intrinsics.cx, calibration.intrinsics.cx);
  EXPECT_EQ(c.intrinsics.cy, calibration.intrinsics.cy);
  EXPECT_EQ(c.intrinsics.distortion, calibration.intrinsics.distortion);
  EXPECT_EQ(c.intrinsics.rms_px, calibration.intrinsics.rms_px);
  EXPECT_EQ(c.intrinsics.body, "Nikon D7500");
  EXPECT_EQ(c.intrinsics.lens, "18-55 @ 24 mm");
  EXPECT_EQ(c.intrinsics.focus, "locked");
  EXPECT_EQ(c.focal_setting_mm, 24);
  EXPECT_EQ(c.method, calibration.method);
  EXPECT_EQ(store.list_calibrations().size(), 2u);

  const Capture got = store.load_capture(capture_id);
  EXPECT_EQ(got.visit_id, visit);
  EXPECT_EQ(got.calibration_id, calibration_id);
  EXPECT_EQ(got.label, capture.label);
  EXPECT_EQ(got.taken_at, capture.taken_at);
  EXPECT_EQ(got.left.bytes, capture.left.bytes);
  EXPECT_EQ(got.right.bytes, capture.right.bytes);
  EXPECT_EQ(got.left.format, "jpeg");
  EXPECT_EQ(got.right.format, "png");  // sample seed 1: the right image is a PNG
  EXPECT_EQ(got.settings, capture.settings);
  EXPECT_EQ(got.left_exif, capture.left_exif);
  EXPECT_EQ(got.right_exif, capture.right_exif);
  EXPECT_EQ(store.load_capture_image(capture_id, "right").bytes, capture.right.bytes);
  const auto summaries = store.list_captures(visit);
  ASSERT_EQ(summaries.size(), 1u);
  EXPECT_EQ(summaries[0].left_bytes, static_cast<std::int64_t>(capture.left.bytes.size()));

  const Model m = store.load_model(model_id);
  EXPECT_EQ(m.capture_id, capture_id);
  EXPECT_EQ(m.preset, "standard");
  ASSERT_EQ(m.mesh.vertices.size(), model.mesh.vertices.size());
  for (std::size_t i = 0; i < m.mesh.vertices.size(); ++i)
    expect_same(m.mesh.vertices[i], model.mesh.vertices[i]);
  EXPECT_EQ(m.mesh.faces, model.mesh.faces);
  EXPECT_EQ(m.mesh.texcoords, model.mesh.texcoords);
  EXPECT_EQ(m.mesh.colours, model.mesh.colours);
  EXPECT_EQ(m.texture_capture_id, capture_id);
  EXPECT_EQ(m.texture_side, "left");
  EXPECT_EQ(m.registration.kind, model.registration.kind);
  EXPECT_EQ(m.registration.scale, model.registration.scale);
  EXPECT_EQ(m.registration.rotation_wxyz, model.registration.rotation_wxyz);
  expect_same(m.registration.translation, model.registration.translation);
  EXPECT_EQ(m.registration.parameters_json, model.registration.parameters_json);
  EXPECT_EQ(m.registration.rms_m, model.registration.rms_m);
  ASSERT_EQ(m.residuals.size(), 2u);
  EXPECT_EQ(m.residuals[1].label, "pole base");
  expect_same(m.residuals[1].residual, model.residuals[1].residual);
  const auto models = store.list_models(capture_id);
  ASSERT_EQ(models.size(), 1u);
  EXPECT_EQ(models[0].vertex_count, 9);
  EXPECT_EQ(models[0].face_count, 8);

  const auto ms = store.list_measurements(visit);
  ASSERT_EQ(ms.size(), measurements.size());
  for (std::size_t i = 0; i < ms.size(); ++i) {
    SCOPED_TRACE(measurements[i].label);
    EXPECT_EQ(ms[i].id, measurement_ids[i]);
    EXPECT_EQ(ms[i].model_id, model_id);
    EXPECT_EQ(ms[i].kind, measurements[i].kind);
    EXPECT_EQ(ms[i].label, measurements[i].label);
    EXPECT_EQ(ms[i].joint_label, measurements[i].joint_label);
    ASSERT_EQ(ms[i].points.size(), measurements[i].points.size());
    for (std::size_t k = 0; k < ms[i].points.size(); ++k)
      expect_same(ms[i].points[k], measurements[i].points[k]);
    EXPECT_EQ(ms[i].dip_deg, measurements[i].dip_deg);
    EXPECT_EQ(ms[i].dipdir_deg, measurements[i].dipdir_deg);
    EXPECT_EQ(ms[i].fit_rms_m, measurements[i].fit_rms_m);
    EXPECT_EQ(ms[i].rock_side, measurements[i].rock_side);
    EXPECT_EQ(ms[i].photo, measurements[i].photo);
    EXPECT_EQ(ms[i].photo_capture_id, measurements[i].photo_capture_id);
    ASSERT_EQ(ms[i].pixels.size(), measurements[i].pixels.size());
    for (std::size_t k = 0; k < ms[i].pixels.size(); ++k)
      EXPECT_EQ(ms[i].pixels[k], measurements[i].pixels[k]);  // JSON keeps doubles exactly
    EXPECT_EQ(ms[i].sigma_deg, measurements[i].sigma_deg);
    EXPECT_EQ(ms[i].trace_length_m, measurements[i].trace_length_m);
    EXPECT_EQ(ms[i].censored, measurements[i].censored);
    EXPECT_EQ(ms[i].note, measurements[i].note);
  }
  EXPECT_FALSE(ms[1].dip_deg.has_value()) << "a collinear trace keeps 'no plane'";

  const auto sets = store.list_joint_sets(visit);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].label, "S1");
  EXPECT_EQ(sets[0].fisher_k, 45.0);
  EXPECT_EQ(sets[0].count, 12);
  EXPECT_EQ(sets[0].alpha95_deg, 4.25);
  EXPECT_EQ(sets[0].spacing_m, 0.8);
  EXPECT_EQ(sets[0].mean_trace_length_m, 2.5);
  EXPECT_EQ(sets[0].censored_traces, 3);
  EXPECT_FALSE(sets[0].persistence_m.has_value());
  EXPECT_EQ(sets[0].note, "3 of 12 traces leave the mapped area");
  EXPECT_FALSE(sets[1].alpha95_deg.has_value());
  const auto joints = store.list_joints(visit);
  const auto expected_joints = test::sample_joints();
  ASSERT_EQ(joints.size(), 3u);
  EXPECT_EQ(joints[0].id, joint_ids[0]);
  EXPECT_EQ(joints[0].set_label, "S1");
  EXPECT_EQ(joints[0].measurement_id, measurement_ids[0]);
  EXPECT_EQ(joints[0].friction_deg, 32);
  EXPECT_EQ(joints[0].cohesion_pa, 15000);
  EXPECT_EQ(joints[0].type, "trace");
  EXPECT_EQ(joints[0].persistence_m, 2.75);
  EXPECT_EQ(joints[1].type, "");
  ASSERT_TRUE(joints[0].point.has_value());
  expect_same(*joints[0].point, *expected_joints[0].point);
  EXPECT_EQ(joints[1].set_label, "S2");
  EXPECT_EQ(joints[1].dipdir_deg, 359.99);
  EXPECT_FALSE(joints[1].friction_deg.has_value());
  EXPECT_EQ(joints[2].set_label, "");
  EXPECT_FALSE(joints[2].point.has_value());
  EXPECT_EQ(joints[2].source, "manual");

  const AnalysisRun a = store.load_analysis(analysis_id);
  EXPECT_EQ(a.visit_id, visit);
  EXPECT_EQ(a.model_id, model_id);
  EXPECT_EQ(a.preset, "precise");
  EXPECT_EQ(a.effects, analysis.effects);
  EXPECT_EQ(a.effects_json, analysis.effects_json);
  ASSERT_EQ(a.blocks.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& want = analysis.blocks[i];
    const auto& b = a.blocks[i];
    EXPECT_EQ(b.label, want.label);
    EXPECT_EQ(b.source, want.source);
    EXPECT_EQ(b.code, want.code);
    EXPECT_EQ(b.volume_m3, want.volume_m3);
    EXPECT_EQ(b.finite, want.finite);
    EXPECT_EQ(b.removable, want.removable);
    EXPECT_EQ(b.marginal, want.marginal);
    EXPECT_EQ(b.mode, want.mode);
    EXPECT_EQ(b.fos, want.fos);
    EXPECT_EQ(b.report_json, want.report_json);
  }
  ASSERT_EQ(store.list_analyses(visit).size(), 1u);
  EXPECT_TRUE(store.list_analyses(visit)[0].blocks.empty()) << "lists carry no blocks";

  // Every save logged itself, in order, in its own transaction.
  std::vector<std::string> actions;
  for (const auto& e : store.list_actions()) actions.push_back(e.action);
  const std::vector<std::string> expected = {
      "project created",   "visit started", "camera body saved",  "calibration saved",
      "calibration saved",  // the recalibration; the repeated save logged nothing
      "capture saved",     "model saved",   "measurements saved", "joints saved",
      "blocks analysed",   "export csv"};
  EXPECT_EQ(actions, expected);
  EXPECT_EQ(store.list_actions(visit).size(), 6u);
  EXPECT_TRUE(store.check_integrity().ok);
}

TEST(ProjectRoundTrip, IdenticalImagesAreStoredOnceAndSecondVisitIsNew) {
  TempDir dir("dedup");
  const auto file = dir / "site.rockface";
  auto store = ProjectStore::create(file, test::sample_project());
  const RecordId first = store.begin_visit("replay captures/day1");
  const Capture capture = test::sample_capture(first, 3, 1024, 768);
  const RecordId a = store.save_capture(capture);
  store.checkpoint();
  const auto size_after_one = std::filesystem::file_size(file);
  const RecordId second = store.begin_visit("replay captures/day1");
  EXPECT_NE(first, second) << "running replay twice gives a second visit";
  Capture again = capture;
  again.visit_id = second;
  const RecordId b = store.save_capture(again);
  store.checkpoint();
  EXPECT_NE(a, b);
  EXPECT_EQ(store.list_captures().size(), 2u);
  EXPECT_EQ(store.list_captures(second).size(), 1u);
  EXPECT_EQ(store.load_capture(b).left.bytes, capture.left.bytes);
  // The second capture adds rows of a few hundred bytes, not the images again
  // (each image is tens of kilobytes).
  const auto image_bytes = capture.left.bytes.size() + capture.right.bytes.size();
  EXPECT_LT(std::filesystem::file_size(file) - size_after_one, image_bytes / 4);
}

TEST(ProjectRoundTrip, BadRecordsAreRefusedWithTheirFieldAndNothingIsSaved) {
  TempDir dir("bad-records");
  auto store = ProjectStore::create(dir / "site.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("tablet");
  const auto actions_before = store.list_actions().size();

  Capture capture = test::sample_capture(visit, 1);
  capture.right.bytes = {'h', 'e', 'l', 'l', 'o'};
  try {
    store.save_capture(capture);
    FAIL() << "a text file was accepted as an image";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("right image"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a JPEG or PNG"), std::string::npos) << e.what();
  }
  capture = test::sample_capture(visit + 100, 1);
  EXPECT_THROW(store.save_capture(capture), InputError);

  auto joints = test::sample_joints();
  joints[2].dip_deg = 95;
  try {
    store.save_joints(visit, test::sample_joint_sets(), joints);
    FAIL() << "dip 95 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "joints[2] (J3).dip");
  }
  joints = test::sample_joints();
  joints[1].set_label = "S9";
  EXPECT_THROW(store.save_joints(visit, {}, joints), InputError) << "unknown set";
  // The failed save left no half: no joint, no set.
  EXPECT_TRUE(store.list_joints(visit).empty());
  EXPECT_TRUE(store.list_joint_sets(visit).empty());

  // Saving the same joint labels twice in one visit is refused.
  store.save_joints(visit, test::sample_joint_sets(), test::sample_joints());
  EXPECT_THROW(store.save_joints(visit, {}, test::sample_joints()), InputError);
  EXPECT_EQ(store.list_joints(visit).size(), 3u);

  auto measurements = test::sample_measurements(std::nullopt);
  measurements[0].rock_side = "upper";
  EXPECT_THROW(store.save_measurements(visit, measurements), InputError) << "trace with rock side";
  measurements = test::sample_measurements(std::nullopt);
  measurements[3].dip_deg.reset();
  measurements[3].dipdir_deg.reset();
  EXPECT_THROW(store.save_measurements(visit, measurements), InputError);
  EXPECT_TRUE(store.list_measurements().empty());

  Model model = test::sample_model(std::nullopt);
  model.mesh.faces.push_back({0, 1, 99});
  EXPECT_THROW(store.save_model(model), InputError);
  EXPECT_TRUE(store.list_models().empty());

  // Only the joints save (and nothing of the refused ones) reached the log.
  EXPECT_EQ(store.list_actions().size(), actions_before + 1);
}

// A further pair of a visit (registration kind "face_images") keeps the map
// from its camera frame apart from its registration; a model registered on
// its own has its registration there. The visit's 3D images come in pair
// order.
TEST(ProjectRoundTrip, AModelKeepsItsCameraMapAndAVisitListsItsPairs) {
  TempDir dir("camera-map");
  auto store = ProjectStore::create(dir / "p.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("replay");
  const RecordId c1 = store.save_capture(test::sample_capture(visit, 1));
  const RecordId c2 = store.save_capture(test::sample_capture(visit, 2));
  const RecordId other = store.save_capture(test::sample_capture(store.begin_visit("x"), 3));
  const Model first = test::sample_model(c1);
  const RecordId m1 = store.save_model(first);
  Model further = test::sample_model(c2);
  further.registration.kind = "face_images";
  photogrammetry::Similarity camera;
  camera.scale = 3.5;
  camera.R = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  camera.t = {4, -5, 6};
  further.camera_to_mesh = camera;
  const RecordId m2 = store.save_model(further);
  Model old_further = test::sample_model(c2);
  old_further.registration.kind = "face_images";
  const RecordId m3 = store.save_model(old_further);
  store.save_model(test::sample_model(other));

  const Model a = store.load_model(m1);
  ASSERT_TRUE(a.camera_to_mesh);
  const photogrammetry::Similarity r = similarity_of(first.registration);
  EXPECT_EQ(a.camera_to_mesh->scale, r.scale);
  expect_same(a.camera_to_mesh->t, r.t);
  // 1e-12: the rotation goes through a quaternion and back (a few ulps).
  EXPECT_LT((a.camera_to_mesh->R - r.R).norm(), 1e-12);
  const Model b = store.load_model(m2);
  ASSERT_TRUE(b.camera_to_mesh);
  EXPECT_EQ(b.camera_to_mesh->scale, 3.5);
  expect_same(b.camera_to_mesh->t, camera.t);
  EXPECT_LT((b.camera_to_mesh->R - camera.R).norm(), 1e-12);
  EXPECT_FALSE(store.load_model(m3).camera_to_mesh) << "a face_images model without one";

  Model bad = further;
  bad.camera_to_mesh->R(0, 0) = 2;
  EXPECT_THROW(store.save_model(bad), InputError);

  // One 3D image per pair, in capture order; a pair's latest model.
  const auto pairs = store.list_visit_models(visit);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].id, m1);
  EXPECT_EQ(pairs[1].id, m3);
}

}  // namespace
}  // namespace rockface::storage
