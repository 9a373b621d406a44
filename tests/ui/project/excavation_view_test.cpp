// Issue 39: Project → Excavation of this round on the tunnel-drive sample's
// project shows the developed view the field report draws (its cells as a
// texture, labelled at the tablet's size), with its legend, and the figures
// in the UI's units (m³, never "m3"), the same figures `rockface profile`
// writes for the visit (a separate process: the reference).
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "tests/support/cli_run.h"
#include "tests/ui/drive_project.h"
#include "tests/ui/drive_tablet.h"
#include "ui/app/app_state.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

TEST(ExcavationView, TheRoundsDevelopedViewWithItsLegendAndFiguresInUnits) {
  test::DriveTablet tablet(test::drive_project());
  ui::HeadlessSession& s = tablet.session;
  ui::AppState& app = s.state();
  tablet.show("Project", "Excavation of this round");
  const auto& t = app.project.tunnel;
  ASSERT_TRUE(t.excavation) << (t.lines.empty() ? "" : t.lines.front());
  ASSERT_TRUE(t.excavation->compared) << t.excavation->message;
  const cv::Mat frame = s.screenshot();
  ASSERT_FALSE(frame.empty());
  EXPECT_TRUE(t.excavation_drawn.view);
  EXPECT_FALSE(t.picture.empty());
  // The colour scale and the swatches: not seen, range pole, beyond tolerance
  // (and the deepest underbreak when there is one).
  EXPECT_GE(t.excavation_drawn.legend_entries, 4);
  ASSERT_FALSE(t.excavation_drawn.figures.empty());
  for (const auto& line : t.excavation_drawn.figures) {
    EXPECT_EQ(line.find("m3"), std::string::npos) << line;
    EXPECT_EQ(line.find("+-"), std::string::npos) << line;
  }
  EXPECT_NE(t.excavation_drawn.figures.front().find(" m³"), std::string::npos)
      << t.excavation_drawn.figures.front();

  // The same round's volumes from the command line.
  const fs::path png = test::ui_test_dir() / "drive-profile.png";
  const fs::path json_file = test::ui_test_dir() / "drive-profile.json";
  const test::CliRun r =
      test::run_rockface("profile " + test::drive_project().string() + " --out " + png.string() +
                         " --json " + json_file.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(json_file);
  const nlohmann::json j = nlohmann::json::parse(in);
  // The JSON rounds volumes to 1 litre (±0.0005 m³).
  EXPECT_NEAR(t.excavation->overbreak_m3, j.at("overbreak_volume_m3").get<double>(),
              0.0005 + 1e-12);
  EXPECT_NEAR(t.excavation->underbreak_m3, j.at("underbreak_volume_m3").get<double>(),
              0.0005 + 1e-12);
}

}  // namespace
