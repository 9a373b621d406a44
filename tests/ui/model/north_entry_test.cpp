// North given on the tablet (issue 42): a visit replayed from a camera's
// card with its range pole but without its compass line is turned as the
// camera stood; on the Model screen the geologist taps the compass line's
// two ends on the photograph, types the bearing read along it, and the
// visit's 3D images are turned to north. Checked against the renderer's
// truth (the left camera's true bearing), not against what the code computes.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/units.h"
#include "storage/project/model_registration.h"
#include "storage/project/project_store.h"
#include "tests/support/card_folder.h"
#include "tests/support/cli_run.h"
#include "tests/support/station_truth.h"
#include "tests/support/temp_folders.h"
#include "tests/ui/field_tablet.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using namespace rockface::ui;
using nlohmann::json;

TEST(NorthEntry, ACompassLineTappedOnThePhotographTurnsTheVisitToNorth) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-north-entry-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::remove_when_passed(dir);
  const json truth = test::render_sample("tunnel-face-demo.scene.json", dir);
  const fs::path card = dir / "card";
  test::write_card(dir / "render", card, "DSC_0001.JPG", "DSC_0002.JPG");
  std::ofstream(card / "visit.json")
      << json{{"format", "rockface-visit/1"}, {"range_pole_m", 2.0}}.dump();
  const fs::path project = dir / "north.rockface";
  const test::CliRun replay = test::run_rockface("replay " + card.string() + " --project " +
                                                 project.string() + " --preset fast");
  ASSERT_EQ(replay.exit_code, 0) << replay.err;

  test::FieldTablet tablet(project);
  HeadlessSession& s = tablet.session;
  AppState& app = s.state();
  ASSERT_TRUE(app.session && app.session->visit());
  s.tap("Model");
  s.settle();
  ASSERT_FALSE(storage::read_model_registration(app.model_view.model()->registration).oriented());
  // Unoriented, the camera's axis is not where its station looked (the demo's
  // looks 5.2 deg east of north): what the turn below must mend.
  const double before =
      std::abs(std::remainder(test::model_axis_bearing_deg(*app.model_view.model()) -
                                  test::true_view_bearing_deg(truth.at("cameras").at(0)),
                              360.0));
  EXPECT_GT(before, 1.0);
  s.tap("Give north from a compass line");
  s.frame();
  ASSERT_TRUE(app.model.show_photograph);

  // The line's ends where the renderer drew them in the left photograph.
  const json& line = truth.at("reference_line");
  const float k = app.model.photo_targets.screen_px_per_photo_px();
  ASSERT_GT(k, 0);
  for (int i = 0; i < 2; ++i) {
    const ImVec2 lo = app.model.photo_targets.image_min();
    const double u = line.at("left")[i][0].get<double>(), v = line.at("left")[i][1].get<double>();
    s.tap(lo.x + static_cast<float>(u + 0.5) * k, lo.y + static_cast<float>(v + 0.5) * k);
  }
  ASSERT_EQ(app.model.north.ends.size(), 2u);
  // The bearing as a compass is read, to a tenth of a degree.
  const double azimuth = line.at("azimuth_deg").get<double>();
  char typed[16];
  std::snprintf(typed, sizeof typed, "%.1f", azimuth);
  for (const char* c = typed; *c; ++c) s.tap(std::string(1, *c));
  s.tap("Give north");
  s.settle();

  auto store = storage::ProjectStore::open(project);
  const storage::Model m = store.load_model(store.list_models().back().id);
  EXPECT_TRUE(storage::read_model_registration(m.registration).oriented());
  ASSERT_TRUE(m.camera_to_mesh);
  // The CLI's 0.5 deg (card_folder_replay_test.cpp: a compass reading's own
  // tolerance; the line fixes north to ~0.1 deg from exact pixels), plus
  // what the taps add: each end lands within half a screen pixel, 0.5 / k
  // photograph pixels, turning the line by up to (1 / k) / length rad, and
  // the bearing typed to 0.05 deg.
  const Eigen::Vector2d a(line.at("left")[0][0].get<double>(), line.at("left")[0][1].get<double>());
  const Eigen::Vector2d b(line.at("left")[1][0].get<double>(), line.at("left")[1][1].get<double>());
  const double taps_deg = rad_to_deg((1.0 / k) / (a - b).norm()) + 0.05;
  const double off = std::abs(std::remainder(
      test::model_axis_bearing_deg(m) - test::true_view_bearing_deg(truth.at("cameras").at(0)),
      360.0));
  std::printf("north from the tablet: camera axis %.2f deg from its true bearing (budget %.2f)\n",
              off, 0.5 + taps_deg);
  EXPECT_LT(off, 0.5 + taps_deg);
  EXPECT_FALSE(app.model.north.open) << "the entry closes once north is given";
}

}  // namespace
