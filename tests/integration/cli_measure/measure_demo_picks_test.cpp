// `rockface measure` picks on the demo face replayed at the fast preset
// (one replay for the suite): an area corner off the 3D image refused by
// name with nothing stored, and traces that name their joints ("joint":
// "J1" on two traces) giving a visit whose joints the analysis finds.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "tests/support/cli_run.h"
#include "tests/support/demo_projects.h"
#include "tests/support/json_file.h"
#include "tests/support/test_paths.h"
#include "tests/support/truth_picks.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::CliRun;
using rockface::test::read_json;
using rockface::test::run_rockface;
using rockface::test::write_json;

Eigen::Vector3d pole_of(double dip_deg, double dipdir_deg) {
  const double d = dip_deg * M_PI / 180, a = dipdir_deg * M_PI / 180;
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180 / M_PI;
}

class MeasureDemoPicks : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rockface-demo-picks-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    project_ = dir_ / "site.rockface";
    // The demo face without its picks replayed at the fast preset: the
    // ui_demo_projects fixture's "bare" replay under CTest (the same
    // `rockface replay` of the same scene, once for every suite).
    try {
      rockface::test::copy_of_shared_demo_project("bare", project_);
      replayed_ = true;
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
  static void TearDownTestSuite() {  // kept for a look when a test failed
    if (::testing::UnitTest::GetInstance()->failed_test_count() == 0) fs::remove_all(dir_);
  }
  void SetUp() override { ASSERT_TRUE(replayed_) << "the demo replay failed"; }

  static std::size_t visits() {
    return rockface::storage::ProjectStore::open(project_).list_visits().size();
  }
  static CliRun measure(const std::string& name, const json& picks) {
    write_json(dir_ / (name + ".picks.json"), picks);
    return run_rockface("measure " + project_.string() + " --traces " +
                        (dir_ / (name + ".picks.json")).string() + " --out " +
                        (dir_ / (name + ".measures.json")).string());
  }

  static inline fs::path dir_, project_;
  static inline bool replayed_ = false;
};

json area(const std::vector<std::array<double, 2>>& corners) {
  json polygon = json::array();
  for (const auto& c : corners) polygon.push_back({c[0], c[1]});
  return {{"format", "rockface-picks/1"},
          {"areas", {{{"id", "A1"}, {"photo", "left"}, {"polygon", polygon}}}}};
}

// An area's corner at u = 1420 px, beyond the east border of the surface
// dense matching leaves (80 px in from the 1500 px photograph's sides,
// tests/support/truth_picks.h): refused by name, exit 2, nothing stored;
// the same area with that corner on the face is stored with every corner.
TEST_F(MeasureDemoPicks, AnAreaCornerOffTheSurfaceIsRefusedByName) {
  const std::size_t before = visits();
  const CliRun off =
      measure("corner-off", area({{{1000, 700}}, {{1000, 310}}, {{1420, 310}}, {{1300, 700}}}));
  EXPECT_EQ(off.exit_code, 2) << off.err;
  EXPECT_NE(off.err.find((dir_ / "corner-off.picks.json").string() +
                         ": areas[0].polygon[2]: pixel (1420, 310) of the left photograph "
                         "hits no surface of the 3D image: move the corner onto the mapped face"),
            std::string::npos)
      << off.err;
  EXPECT_FALSE(fs::exists(dir_ / "corner-off.measures.json"));
  EXPECT_EQ(visits(), before) << "nothing stored";

  const std::vector<std::array<double, 2>> on{{1000, 700}, {1000, 310}, {1300, 310}, {1300, 700}};
  const CliRun r = measure("corner-on", area(on));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto store = rockface::storage::ProjectStore::open(project_);
  const auto visit = store.latest_visit();
  ASSERT_TRUE(visit.has_value());
  const auto stored = store.list_measurements(*visit);
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].label, "A1");
  // Every corner tapped, each with its 3D point (the order may be turned
  // to face the camera, free_face_side.h).
  ASSERT_EQ(stored[0].pixels.size(), on.size());
  ASSERT_EQ(stored[0].points.size(), on.size());
  for (const auto& c : on)
    EXPECT_NE(
        std::find(stored[0].pixels.begin(), stored[0].pixels.end(), Eigen::Vector2d(c[0], c[1])),
        stored[0].pixels.end())
        << c[0] << ", " << c[1];
  const json exported =
      rockface::storage::make_scene_json(rockface::storage::load_scene_source(store, *visit));
  EXPECT_EQ(exported.at("surface").at("patches").at(0).at("polygon").size(), on.size());
}

// The sample's taps of its traces with their joint names as the geologist
// gave them (T1, T2: J1 across the fold; T3: J2, with its compass reading;
// T4, T5: J3), and the demo's two walls outlined as free faces (as in
// free_face_winding_test.cpp), so that the visit holds all the analysis
// needs.
json named_joint_picks() {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json");
  const json sample = json::parse(in);
  json traces = json::array();
  for (const json& t : sample.at("picks").at("traces"))
    if (t.contains("pixels")) traces.push_back(t);
  json areas = json::array();
  const std::vector<std::vector<std::array<double, 2>>> walls{
      {{150, 60}, {150, 940}, {749.2, 940}, {746.0, 60}},
      {{746.0, 60}, {749.2, 940}, {1350, 940}, {1350, 60}}};
  for (std::size_t k = 0; k < walls.size(); ++k) {
    json polygon = json::array();
    for (const auto& c : walls[k]) polygon.push_back({c[0], c[1]});
    areas.push_back({{"id", k == 0 ? "FW" : "FE"},
                     {"photo", "left"},
                     {"polygon", polygon},
                     {"rock_side", "lower"}});
  }
  return {{"format", "rockface-picks/1"}, {"traces", traces}, {"areas", areas}};
}

TEST_F(MeasureDemoPicks, TracesNamingAJointGiveThatJointFittedToThemAll) {
  const CliRun r = measure("named", named_joint_picks());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  EXPECT_NE(r.out.find("J1 (traces T1 T2): joint "), std::string::npos) << r.out;

  auto store = rockface::storage::ProjectStore::open(project_);
  const auto visit = store.latest_visit();
  ASSERT_TRUE(visit.has_value());
  std::map<std::string, rockface::storage::Joint> joints;
  for (const auto& j : store.list_joints(*visit)) joints[j.label] = j;
  ASSERT_TRUE(joints.count("J1")) << "the joint the traces name is stored";
  const auto& j1 = joints.at("J1");
  // As `rockface replay` stores a joint fitted to several traces.
  EXPECT_EQ(j1.source, "traces T1 T2");
  EXPECT_EQ(j1.type, "trace");
  ASSERT_TRUE(j1.point.has_value());
  // One discontinuity, one joint: its traces have none of their own.
  EXPECT_FALSE(joints.count("T1"));
  EXPECT_FALSE(joints.count("T2"));

  // The orientation of the demo scene's J1 (60/200). Expected error: the
  // fit's own sigma (MEASURES.json joints[].sigma_deg: the 3D image's
  // noise, 14 mm at the fast preset, over the relief of both traces across
  // the fold) to 3 sigma, plus the registration's vertical and north
  // (~0.1 deg, replay_face_picks_test.cpp), taken as 0.2 deg.
  double sigma = -1;
  const json measures = read_json(dir_ / "named.measures.json");
  for (const auto& j : measures.at("joints"))
    if (j.at("label") == "J1" && j.at("orientation_known").get<bool>())
      sigma = j.at("sigma_deg").get<double>();
  ASSERT_GT(sigma, 0) << "J1's plane is known in MEASURES.json";
  double scene_dip = 0, scene_dipdir = 0;
  const json demo = rockface::test::demo_scene();
  for (const auto& j : demo.at("joints"))
    if (j.at("id") == "J1") {
      scene_dip = j.at("dip").get<double>();
      scene_dipdir = j.at("dipdir").get<double>();
    }
  const double e = angle_deg(pole_of(j1.dip_deg, j1.dipdir_deg), pole_of(scene_dip, scene_dipdir));
  std::printf("J1 measured %.2f/%.2f (sigma %.2f deg), scene %.0f/%.0f: %.2f deg off\n", j1.dip_deg,
              j1.dipdir_deg, sigma, scene_dip, scene_dipdir, e);
  EXPECT_LT(e, 3 * sigma + 0.2);

  // The visit as the tablet's analysis exports it: every trace's joint is
  // in its joint table, and the analysis takes it.
  const json scene =
      rockface::storage::make_scene_json(rockface::storage::load_scene_source(store, *visit));
  std::map<std::string, json> scene_joints;
  for (const auto& j : scene.at("joints")) scene_joints[j.at("id").get<std::string>()] = j;
  for (const auto& t : scene.at("traces")) {
    if (!t.contains("joint")) continue;
    EXPECT_TRUE(scene_joints.count(t.at("joint").get<std::string>())) << t.dump();
  }
  write_json(dir_ / "named.scene.json", scene);
  const CliRun a = run_rockface("analyse " + (dir_ / "named.scene.json").string() + " --out " +
                                (dir_ / "named.report.json").string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  // The demo's keyblock (J1 x J2 x J3 on the face, from the traces T1-T5):
  // finite and removable, as free_face_winding_test.cpp finds it from the
  // traces' own joints.
  const json report = read_json(dir_ / "named.report.json");
  ASSERT_GE(report.at("blocks").size(), 1u) << report.at("notes").dump(1);
  EXPECT_TRUE(report.at("blocks")[0].at("finite").get<bool>());
  EXPECT_TRUE(report.at("blocks")[0].at("removable").get<bool>());
}

// A joint named by one straight trace (T4 alone, on the flat west wall):
// its traces give no plane, so no joint is stored, and that is said by name
// (the verb, the visit's note, the trace's record), not dropped in silence;
// the trace names no joint the visit lacks, so the analysis still takes it.
TEST_F(MeasureDemoPicks, ANamedJointWhoseTracesGiveNoPlaneIsSaidByName) {
  json picks = named_joint_picks();
  json traces = json::array();
  for (json t : picks.at("traces"))
    if (t.at("id") == "T4") {
      t["joint"] = "JX";
      traces.push_back(t);
    }
  ASSERT_EQ(traces.size(), 1u);
  picks["traces"] = traces;
  const CliRun r = measure("planeless", picks);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("JX (traces T4): no joint stored: orientation unknown: "), std::string::npos)
      << r.out;

  auto store = rockface::storage::ProjectStore::open(project_);
  const auto visits = store.list_visits();
  ASSERT_FALSE(visits.empty());
  const auto& visit = visits.back();
  EXPECT_NE(visit.note.find("joint JX: orientation unknown: "), std::string::npos) << visit.note;
  for (const auto& j : store.list_joints(visit.id)) EXPECT_NE(j.label, "JX");
  bool found = false;
  for (const auto& m : store.list_measurements(visit.id))
    if (m.label == "T4") {
      found = true;
      EXPECT_EQ(m.joint_label, "");
      EXPECT_NE(m.note.find("named joint JX, not stored (traces T4): orientation unknown: "),
                std::string::npos)
          << m.note;
    }
  EXPECT_TRUE(found);
  write_json(
      dir_ / "planeless.scene.json",
      rockface::storage::make_scene_json(rockface::storage::load_scene_source(store, visit.id)));
  const CliRun a = run_rockface("analyse " + (dir_ / "planeless.scene.json").string() + " --out " +
                                (dir_ / "planeless.report.json").string());
  EXPECT_EQ(a.exit_code, 0) << a.err;
}

// A joint name that is also the id of a measurement that has a joint of its
// own (a point with its local plane): two joints of one label, refused by
// name before anything is stored.
TEST_F(MeasureDemoPicks, AJointNamedAsAMeasurementIsRefused) {
  json picks = named_joint_picks();
  for (auto& t : picks.at("traces"))
    if (t.at("joint") == "J1") t["joint"] = "P1";
  picks["points"] = {{{"id", "P1"}, {"photo", "left"}, {"pixel", {1100, 700}}, {"radius", 0.3}}};
  const std::size_t before = visits();
  const CliRun r = measure("clash", picks);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find((dir_ / "clash.picks.json").string() +
                       ": traces (joint P1): the joint name \"P1\" is also the id of a "
                       "measured point"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(visits(), before) << "nothing stored";
}

}  // namespace
