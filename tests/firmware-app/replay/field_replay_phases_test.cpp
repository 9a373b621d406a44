#include "firmware-app/replay/field_replay_phases.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "camera/synthetic_renderer.h"
#include "core/common/error.h"
#include "core/common/units.h"
#include "tests/support/test_paths.h"

namespace rockface::app::field_replay_phases {
namespace {

using Eigen::Vector3d;

storage::Scene sample(const std::string& name) {
  return storage::load_scene(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/" + name);
}

bool on_face(const std::string& patch) {
  return patch.rfind("FACE", 0) == 0;
}

// The rendered tunnel of tunnel-drive.scene.json: walls of many facets and a
// face; the scene gives no patches and no traces of its own.
class RenderedTunnel : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = sample("tunnel-drive.scene.json");
    synthetic_ = synthetic_scene_from_scene(scene_);
  }
  storage::Scene scene_;
  SyntheticSceneInput synthetic_;
};

TEST_F(RenderedTunnel, ItsFreeSurfaceIsItsFaceInAbsoluteCoordinates) {
  const std::vector<analysis::ScenePatch> face = rendered_face(synthetic_);
  const auto faces = std::count_if(synthetic_.scene.patches.begin(), synthetic_.scene.patches.end(),
                                   [](const auto& p) { return on_face(p.id); });
  ASSERT_GT(faces, 0);
  ASSERT_LT(static_cast<std::size_t>(faces), synthetic_.scene.patches.size());  // walls too
  ASSERT_EQ(face.size(), static_cast<std::size_t>(faces));
  for (const auto& p : face) EXPECT_TRUE(on_face(p.id)) << p.id;
  const auto first = std::find_if(synthetic_.scene.patches.begin(), synthetic_.scene.patches.end(),
                                  [](const auto& p) { return on_face(p.id); });
  ASSERT_EQ(face[0].polygon.size(), first->polygon.size());
  EXPECT_EQ(face[0].polygon[0], first->polygon[0] + synthetic_.origin);
}

TEST_F(RenderedTunnel, TheGeologistMapsOnlyTheFacesTraces) {
  const std::vector<analysis::SceneTrace> traces = true_face_traces(scene_, synthetic_);
  std::vector<camera::TraceSegment> on_the_face;
  for (const auto& seg : camera::true_trace_segments(synthetic_.scene))
    if (on_face(seg.patch)) on_the_face.push_back(seg);
  ASSERT_FALSE(on_the_face.empty());
  ASSERT_EQ(traces.size(), on_the_face.size());
  for (std::size_t i = 0; i < traces.size(); ++i) {
    EXPECT_EQ(traces[i].id, "T" + std::to_string(i + 1));
    EXPECT_EQ(traces[i].joint, on_the_face[i].joint);
    ASSERT_EQ(traces[i].points.size(), 2u);
    EXPECT_EQ(traces[i].points[1], on_the_face[i].world[1] + synthetic_.origin);
  }
}

TEST_F(RenderedTunnel, TheAnalysisInputTakesTheFaceWhereTheSceneHasNoPatches) {
  ASSERT_TRUE(scene_.patches.empty());
  const analysis::AnalysisInput input = replay_analysis_input(scene_, synthetic_, nullptr, "s");
  EXPECT_EQ(input.patches.size(), rendered_face(synthetic_).size());
  EXPECT_EQ(input.traces.size(), true_face_traces(scene_, synthetic_).size());
}

TEST(ReplayAnalysisInput, AFaceOutsideATunnelGivesAllItsTrueTraces) {
  const storage::Scene scene = sample("tunnel-face.scene.json");
  const SyntheticSceneInput synthetic = synthetic_scene_from_scene(scene);
  ASSERT_FALSE(scene.tunnel);
  EXPECT_EQ(true_face_traces(scene, synthetic).size(),
            camera::true_trace_segments(synthetic.scene).size());
}

TEST(ReplayAnalysisInput, MeasuredTracesAndJointsReplaceTheScenes) {
  const storage::Scene scene = sample("tunnel-face.scene.json");
  const SyntheticSceneInput synthetic = synthetic_scene_from_scene(scene);
  ReplayPicks picked;
  picked.traces = {{"P1", std::string("J1"), {Vector3d(1, 2, 3), Vector3d(2, 2, 3)}}};
  picked.joints = {{"J1", 61.0, 118.0, std::nullopt, 30.0, std::nullopt}};
  const analysis::AnalysisInput input = replay_analysis_input(scene, synthetic, &picked, "s");
  ASSERT_EQ(input.traces.size(), 1u);
  EXPECT_EQ(input.traces[0].id, "P1");
  ASSERT_EQ(input.joints.size(), 1u);
  EXPECT_EQ(input.joints[0].dip, 61.0);
  EXPECT_EQ(input.patches.size(), scene.patches.size());
}

TEST(ReplayAnalysisInput, ASceneWithoutFreeSurfaceIsRefusedNamingTheSource) {
  storage::Scene scene = sample("tunnel-face.scene.json");
  const SyntheticSceneInput synthetic = synthetic_scene_from_scene(scene);
  scene.patches.clear();
  try {
    replay_analysis_input(scene, synthetic, nullptr, "the-scene.json");
    FAIL() << "analysed a scene without a free surface";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the-scene.json"), std::string::npos) << what;
    EXPECT_NE(what.find("surface.patches"), std::string::npos) << what;
  }
}

analysis::AnalysisInput two_traces_one_patch() {
  analysis::AnalysisInput input;
  input.traces = {{"T1", std::string("J1"), {Vector3d(101, 202, 303), Vector3d(102, 202, 303)}},
                  {"T2", std::nullopt, {Vector3d(100, 201, 300)}}};
  input.patches = {
      {"F1", {Vector3d(100, 200, 300), Vector3d(101, 200, 300), Vector3d(101, 200, 301)}}};
  input.joints = {{"J1", 60, 120, Vector3d(110, 210, 310), 32.0, 1e4},
                  {"J2", 45, 300, std::nullopt, std::nullopt, std::nullopt}};
  return input;
}

TEST(VisitMeasurements, TracesThenAreasDatumRelativeWithTheirJoint) {
  const Vector3d datum(100, 200, 300);
  const auto m = visit_measurements(two_traces_one_patch(), nullptr, nullptr, {7, 8, 9}, datum);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].kind, storage::Measurement::Kind::trace);
  EXPECT_EQ(m[0].label, "T1");
  EXPECT_EQ(m[0].joint_label, "J1");
  EXPECT_EQ(m[0].points[0], Vector3d(1, 2, 3));
  EXPECT_EQ(m[1].joint_label, "");
  EXPECT_EQ(m[2].kind, storage::Measurement::Kind::area);
  EXPECT_EQ(m[2].label, "F1");
  EXPECT_EQ(m[2].points.size(), 3u);
  EXPECT_EQ(m[2].points[2], Vector3d(1, 0, 1));
  for (const auto& x : m) {
    EXPECT_EQ(x.visit_id, 7);
    EXPECT_EQ(x.model_id, 8);
  }
}

TEST(VisitJoints, FromTheSceneUnlessTheirTracesGaveThePlane) {
  const Vector3d datum(100, 200, 300);
  const analysis::AnalysisInput input = two_traces_one_patch();
  const auto from_scene = visit_joints(input, nullptr, 7, datum);
  ASSERT_EQ(from_scene.size(), 2u);
  EXPECT_EQ(from_scene[0].source, "scene");
  ASSERT_TRUE(from_scene[0].point);
  EXPECT_EQ(*from_scene[0].point, Vector3d(10, 10, 10));
  EXPECT_EQ(from_scene[0].friction_deg, 32.0);
  EXPECT_FALSE(from_scene[1].point);

  ReplayPicks picked;
  measure::MeasuredJoint j1;
  j1.label = "J1";
  j1.traces = {"T1", "T4"};
  j1.plane.known = true;
  measure::MeasuredJoint j2;  // its traces gave no plane: stays the scene's
  j2.label = "J2";
  j2.traces = {"T2"};
  picked.measured.joints = {j1, j2};
  const auto joints = visit_joints(input, &picked, 7, datum);
  ASSERT_EQ(joints.size(), 2u);
  EXPECT_EQ(joints[0].source, "traces T1 T4");
  EXPECT_EQ(joints[0].type, "trace");
  EXPECT_EQ(joints[1].source, "scene");
  EXPECT_EQ(joints[1].visit_id, 7);
}

TEST(MoveToPole, ThePolesLowerTargetLandsWhereThePoleStood) {
  photogrammetry::ReconstructionResult rec;
  rec.model_to_world.scale = 2;
  rec.model_to_world.t = Vector3d(0.5, -1, 2);
  rec.targets.emplace();
  rec.targets->model = {Vector3d(0.1, 0.2, 3), Vector3d(0.1, 0.0, 3)};
  rec.mesh.vertices = {Vector3d(1, 1, 1), Vector3d(-3, 4, 0)};
  const Vector3d pole(12, 30, -1.5);
  const Vector3d shift = pole - rec.model_to_world.apply(rec.targets->model[0]);
  move_to_pole(rec, pole);
  // Sums of a few metres: exact to rounding.
  EXPECT_LT((rec.model_to_world.apply(rec.targets->model[0]) - pole).norm(), 1e-12);
  EXPECT_LT((rec.mesh.vertices[1] - (Vector3d(-3, 4, 0) + shift)).norm(), 1e-12);
}

TEST(JointComparisons, EachPickedJointBesideTheScenesPlane) {
  storage::Scene scene;
  scene.joints = {{"J1", 60, 120, std::nullopt, std::nullopt, std::nullopt},
                  {"J2", 30, 10, std::nullopt, std::nullopt, std::nullopt}};
  measure::MeasuredPicks measured;
  measure::MeasuredJoint j1;
  j1.label = "J1";
  j1.traces = {"T1"};
  j1.plane.known = true;
  j1.plane.orientation = {deg_to_rad(62.0), deg_to_rad(120.0)};
  measure::MeasuredJoint j3;  // not a scene joint: no comparison
  j3.label = "J3";
  measured.joints = {j1, j3};
  const auto c = joint_comparisons(scene, measured);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].id, "J1");
  EXPECT_TRUE(c[0].measured);
  // Same dip direction: the planes differ by the dip, 2 degrees; only
  // rounding is left (acos of 0.99939, far from 1 where it loses digits).
  EXPECT_NEAR(c[0].angle, 2.0, 1e-6);
  EXPECT_EQ(c[0].traces, std::vector<std::string>{"T1"});
}

}  // namespace
}  // namespace rockface::app::field_replay_phases
