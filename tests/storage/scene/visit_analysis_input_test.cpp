// Issue 37: the tablet builds a visit's analysis input from the project's
// rows (storage::visit_analysis_input), no scene JSON text in between. It
// must be the input the scene reader makes of the visit's scene export
// (make_scene_json), value for value, and refuse what the reader refuses in
// the reader's words.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "storage/scene/scene.h"
#include "tests/support/dense_face_visit.h"
#include "tests/support/refusal.h"
#include "tests/support/temp_folders.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using rockface::test::refusal;

fs::path test_dir() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("rockface-visit-input-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    rockface::test::remove_when_passed(d);
    return d;
  }();
  return dir;
}

const std::string kName = "P.rockface visit 1";

// The scene reader's input of the visit: its scene export, parsed.
storage::Scene read_back(const storage::SceneSource& source) {
  return storage::parse_scene(storage::make_scene_json(source).dump(), kName);
}

// Every value the analysis reads, compared exactly: the JSON text writes
// each double so that it reads back to the same bits.
void expect_same(const analysis::AnalysisInput& in, const storage::Scene& s) {
  EXPECT_EQ(in.source, s.source);
  EXPECT_EQ(in.datum, s.datum);
  EXPECT_EQ(in.has_datum, s.has_datum);
  EXPECT_EQ(in.density, s.density);
  EXPECT_EQ(in.gravity, s.gravity);
  ASSERT_EQ(in.joints.size(), s.joints.size());
  for (std::size_t k = 0; k < s.joints.size(); ++k) {
    SCOPED_TRACE("joint " + s.joints[k].id);
    EXPECT_EQ(in.joints[k].id, s.joints[k].id);
    EXPECT_EQ(in.joints[k].dip, s.joints[k].dip);
    EXPECT_EQ(in.joints[k].dipdir, s.joints[k].dipdir);
    EXPECT_EQ(in.joints[k].point, s.joints[k].point);
    EXPECT_EQ(in.joints[k].friction, s.joints[k].friction);
    EXPECT_EQ(in.joints[k].cohesion, s.joints[k].cohesion);
  }
  ASSERT_EQ(in.free_faces.size(), s.free_faces.size());
  for (std::size_t k = 0; k < s.free_faces.size(); ++k) {
    EXPECT_EQ(in.free_faces[k].id, s.free_faces[k].id);
    EXPECT_EQ(in.free_faces[k].dip, s.free_faces[k].dip);
    EXPECT_EQ(in.free_faces[k].dipdir, s.free_faces[k].dipdir);
    EXPECT_EQ(in.free_faces[k].point, s.free_faces[k].point);
    EXPECT_EQ(in.free_faces[k].rock_side, s.free_faces[k].rock_side);
    EXPECT_EQ(in.free_faces[k].group, s.free_faces[k].group);
  }
  EXPECT_TRUE(in.blocks.empty());
  EXPECT_TRUE(s.blocks.empty());
  ASSERT_EQ(in.patches.size(), s.patches.size());
  for (std::size_t k = 0; k < s.patches.size(); ++k) {
    EXPECT_EQ(in.patches[k].id, s.patches[k].id);
    EXPECT_EQ(in.patches[k].polygon, s.patches[k].polygon);
  }
  ASSERT_EQ(in.traces.size(), s.traces.size());
  for (std::size_t k = 0; k < s.traces.size(); ++k) {
    SCOPED_TRACE("trace " + s.traces[k].id);
    EXPECT_EQ(in.traces[k].id, s.traces[k].id);
    EXPECT_EQ(in.traces[k].joint, s.traces[k].joint);
    EXPECT_EQ(in.traces[k].points, s.traces[k].points);
  }
  EXPECT_EQ(in.analysis.preset, s.analysis.preset);
  EXPECT_EQ(in.analysis.pyramids, s.analysis.pyramids);
  EXPECT_EQ(in.analysis.blocks, s.analysis.blocks);
  EXPECT_EQ(in.analysis.stability, s.analysis.stability);
  EXPECT_EQ(in.effects.listed(), s.effects.listed());
  ASSERT_EQ(in.effects.water.has_value(), s.effects.water.has_value());
  if (s.effects.water) {
    EXPECT_EQ(in.effects.water->unit_weight, s.effects.water->unit_weight);
    EXPECT_EQ(in.effects.water->phreatic_point, s.effects.water->phreatic_point);
    EXPECT_EQ(in.effects.water->joints, s.effects.water->joints);
  }
  EXPECT_EQ(in.effects.seismic, s.effects.seismic);
  ASSERT_EQ(in.effects.joint_law.has_value(), s.effects.joint_law.has_value());
  if (s.effects.joint_law) {
    EXPECT_EQ(in.effects.joint_law->jrc, s.effects.joint_law->jrc);
    EXPECT_EQ(in.effects.joint_law->model, s.effects.joint_law->model);
  }
}

// The dense face's visit, with a patch that is no free face, a trace that
// lies in a joint of its own only, and an analysis run that names its
// preset and its effects.
storage::SceneSource dense_visit(const fs::path& file) {
  const test::DenseFace face = test::dense_face(12);
  const storage::RecordId visit = test::make_dense_visit(file, face, 12);
  storage::ProjectStore store = storage::ProjectStore::open(file);
  storage::Measurement area = test::face_area(face);
  area.label = "S2";
  area.rock_side.clear();
  storage::Measurement own = test::trace_measurement(face.traces[11]);
  own.label = "T99";
  own.joint_label.clear();
  store.save_measurements(visit, {area, own});
  storage::Joint joint = test::joint_of(face.traces[11]);
  joint.label = "T99";
  joint.source = "trace T99 (compass)";
  store.save_joints(visit, {}, {joint});
  storage::AnalysisRun run;
  run.visit_id = visit;
  run.preset = "fast";
  run.effects = {"gravity", "water", "seismic"};
  run.effects_json = R"({"water": {"phreatic_surface": {"point": [2690000.0, 1170000.0, 1105.5],
      "dip": 0, "dipdir": 0}, "joints": ["J1", "J2"]}, "seismic": {"acceleration": [0.3, 0.1, 0]},
      "joint_law": {"model": "coulomb", "jrc": 7.5}})";
  store.save_analysis(run);
  return storage::load_scene_source(store, visit);
}

TEST(VisitAnalysisInput, IsTheInputTheSceneReaderMakesOfTheVisitsSceneExport) {
  storage::SceneSource source = dense_visit(test_dir() / "dense.rockface");
  // The store keeps dip directions below 360; the reader takes 360 as 0.
  source.joints.back().dipdir_deg = 360;
  const analysis::AnalysisInput in = storage::visit_analysis_input(source, kName);
  const storage::Scene scene = read_back(source);
  expect_same(in, scene);
  // The test reaches what it means to: a free face and a plain patch, a
  // trace in a joint of its own, the stored preset and effects.
  EXPECT_EQ(in.free_faces.size(), 1u);
  EXPECT_EQ(in.patches.size(), 2u);
  EXPECT_EQ(in.traces.back().joint, std::optional<std::string>("T99"));
  EXPECT_EQ(in.joints.back().dipdir, 0);
  EXPECT_EQ(in.analysis.preset, Preset::fast);
  EXPECT_EQ(in.effects.listed(),
            (std::vector<std::string>{"gravity", "water", "seismic", "joint_law"}));
}

// What the reader refuses in a visit's scene, the direct build refuses in
// the same words.
TEST(VisitAnalysisInput, RefusesWhatTheSceneReaderRefusesInItsWords) {
  const storage::SceneSource good = dense_visit(test_dir() / "bad.rockface");
  auto same_refusal = [&](const storage::SceneSource& bad, const std::string& field) {
    const std::string direct = refusal([&] { storage::visit_analysis_input(bad, kName); });
    EXPECT_EQ(direct, refusal([&] { read_back(bad); }));
    EXPECT_EQ(direct.rfind(kName + ": " + field + ": ", 0), 0u) << direct;
  };
  storage::SceneSource bad = good;
  bad.measurements.back().joint_label = "J404";  // T99 names a joint the visit lacks
  same_refusal(bad, "traces[12].joint");
  bad = good;
  bad.joints[3].dip_deg = 95;
  same_refusal(bad, "joints[3].dip");
  bad = good;
  bad.measurements.front().rock_side = "sideways";
  same_refusal(bad, "free_faces[0].rock_side");
  bad = good;
  bad.measurements.front().points.resize(2);
  same_refusal(bad, "surface.patches[0].polygon");
  bad = good;
  bad.joints[1].label = bad.joints[0].label;
  same_refusal(bad, "joints[1].id");
  bad = good;
  bad.analysis->preset = "best";
  same_refusal(bad, "analysis.preset");
  bad = good;
  bad.analysis->effects_json = R"({"water": {"phreatic_surface": {"point": [0, 0, 0], "dip": 0,
      "dipdir": 0}, "joints": ["J404"]}})";
  same_refusal(bad, "effects.water.joints[0]");
  bad = good;
  bad.analysis->effects_json = R"({"joint_law": {"jrc": 25}})";
  same_refusal(bad, "effects.joint_law.jrc");
}

}  // namespace
