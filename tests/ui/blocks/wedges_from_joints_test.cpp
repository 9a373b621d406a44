// Issue 39: wedges from a visit's joints when they form no sets. The
// tunnel-drive sample's visit has three joints (one trace or more each) and
// no joint set; a geologist who measured one joint per orientation expects
// their wedges, as UnWedge takes three orientations. Checked against the
// wedges of the three true orientations and frictions read from the scene
// file (not from the project or the code under test), on the command line
// and on the tablet's Wedges view.
#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/geometry/orientation.h"
#include "core/tunnel/wedge_analysis.h"
#include "firmware-app/wedges/wedge_input.h"
#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"
#include "tests/ui/drive_project.h"
#include "tests/ui/drive_tablet.h"
#include "ui/app/app_state.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using nlohmann::json;

constexpr double kRad = 3.14159265358979323846 / 180.0;

// The wedges of the scene's own three joints (orientation and friction as
// the scene file writes them) around the same section as the visit's run.
tunnel::WedgeAnalysis true_wedges() {
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(test::drive_project(), read);
  const auto visit = store.latest_visit();
  if (!visit) throw std::runtime_error("the drive project has no visit");
  const app::WedgeRun run = app::wedge_run_from_project(store, *visit, {});
  std::vector<tunnel::WedgeJointSet> sets;
  const json scene = test::drive_scene_json();
  for (const auto& j : scene.at("joints")) {
    tunnel::WedgeJointSet s;
    s.id = j.at("id").get<std::string>();
    s.normal = geometry::plane_normal_deg(j.at("dip").get<double>(), j.at("dipdir").get<double>());
    s.friction = j.at("friction").get<double>() * kRad;
    s.cohesion = j.at("cohesion").get<double>();
    sets.push_back(s);
  }
  return tunnel::analyse_wedges(run.profile, run.frame, run.datum, sets, run.options);
}

TEST(WedgesFromJoints, TheCommandLineGivesTheWedgesOfTheVisitsThreeJoints) {
  const tunnel::WedgeAnalysis truth = true_wedges();
  ASSERT_FALSE(truth.wedges.empty()) << "the scene's joints form wedges around the drive";
  const fs::path out = test::ui_test_dir() / "drive-wedges.json";
  const test::CliRun r =
      test::run_rockface("wedges " + test::drive_project().string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out);
  const json j = json::parse(in);
  // The joints, each a set, with its friction from the visit (the scene's).
  const json scene = test::drive_scene_json();
  ASSERT_EQ(j.at("sets").size(), scene.at("joints").size());
  for (std::size_t k = 0; k < j.at("sets").size(); ++k) {
    const json& s = j["sets"][k];
    const json& t = scene["joints"][k];
    EXPECT_EQ(s.at("source"), "joint");
    EXPECT_EQ(s.at("id"), t.at("id"));
    // JSON rounds orientations and friction to 0.1 deg.
    EXPECT_NEAR(s.at("dip").get<double>(), t.at("dip").get<double>(), 0.05);
    EXPECT_NEAR(s.at("dipdir").get<double>(), t.at("dipdir").get<double>(), 0.05);
    EXPECT_NEAR(s.at("friction_deg").get<double>(), t.at("friction").get<double>(), 0.05);
  }
  bool said = false;
  for (const auto& n : j.at("notes"))
    said = said || n.get<std::string>().find("3 joints, each taken as a set") != std::string::npos;
  EXPECT_TRUE(said) << j.at("notes").dump();
  // The same wedges as the true orientations give.
  ASSERT_EQ(j.at("wedges").size(), truth.wedges.size());
  for (std::size_t k = 0; k < truth.wedges.size(); ++k) {
    const tunnel::Wedge& t = truth.wedges[k];
    const json& w = j["wedges"][k];
    EXPECT_EQ(w.at("code"), t.code);
    EXPECT_EQ(w.at("place"), tunnel::wedge_place_name(t.place));
    // The JSON's rounding (1e-4 m³, FoS to 0.001); the joints are stored at
    // the scene's orientations, so nothing else separates them.
    EXPECT_NEAR(w.at("volume_m3").get<double>(), t.mass.volume, 0.5e-4 + 1e-9);
    if (t.fos && std::isfinite(*t.fos)) {
      EXPECT_NEAR(w.at("fos").get<double>(), *t.fos, 0.5e-3 + 1e-9) << t.id;
    }
  }
}

TEST(WedgesFromJoints, TheTabletsWedgesViewShowsThem) {
  const tunnel::WedgeAnalysis truth = true_wedges();
  test::DriveTablet tablet(test::drive_project());
  ui::HeadlessSession& s = tablet.session;
  ui::AppState& app = s.state();
  tablet.find_wedges();
  const auto& w = app.blocks.wedges;
  ASSERT_TRUE(w.table) << w.message;
  ASSERT_EQ(w.table->rows.size(), truth.wedges.size());
  for (std::size_t k = 0; k < truth.wedges.size(); ++k)
    EXPECT_EQ(w.table->rows[k][2], truth.wedges[k].code);
  bool joints = false;
  for (const auto& line : w.table->lines)
    joints = joints || line.rfind("Joints, each taken", 0) == 0;
  EXPECT_TRUE(joints);
  s.screenshot();  // the table drawn
  EXPECT_TRUE(app.targets.find("wedge " + truth.wedges.front().id));
}

}  // namespace
