// Issue 38: a visit nothing scaled (no range pole, control points or
// baseline) has its lengths in units of the camera base. `replay` says so
// instead of printing its precision in millimetres, and `propose`, whose
// thresholds are metres and square metres, refuses it by name instead of
// applying them to base lengths.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/card_folder.h"
#include "tests/support/cli_run.h"
#include "tests/support/truth_picks.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::CliRun;
using rockface::test::run_rockface;

TEST(UnscaledVisit, ReplaySaysUnscaledAndProposeRefusesItsMetreThresholds) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-unscaled-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The demo face photographed without its range pole: the truth is that
  // nothing scales this visit (the scene gives no control points either).
  nlohmann::json scene = rockface::test::demo_scene();
  ASSERT_TRUE(scene.at("imaging").contains("range_pole"));
  scene["imaging"].erase("range_pole");
  ASSERT_FALSE(scene.contains("control_points"));
  { std::ofstream(dir / "face.scene.json") << scene.dump(2); }
  const fs::path project = dir / "site.rockface";
  CliRun r = run_rockface("replay " + (dir / "face.scene.json").string() + " --project " +
                          project.string() + " --preset fast");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scale: none"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("base lengths: unscaled"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" mm)"), std::string::npos) << r.out;

  const auto bytes = fs::file_size(project);
  r = run_rockface("propose " + project.string() + " --out " + (dir / "p.json").string() +
                   " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("visit 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("unscaled"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "p.json"));
  EXPECT_EQ(fs::file_size(project), bytes);
  fs::remove_all(dir);
}

// The same from a camera's card: the demo face's pair as JPEGs with its
// camera.json and no visit file, no --range-pole, no --gcp. Nothing scales
// the visit (the truth: nothing in the folder or the command gives a
// length), so no figure may come out in millimetres or square metres.
TEST(UnscaledVisit, AFolderOfCapturesWithoutPoleOrControlIsUnscaledEverywhere) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-unscaled-card-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  rockface::test::render_sample("tunnel-face-demo.scene.json", dir);
  ASSERT_FALSE(HasFailure());
  const fs::path card = dir / "DCIM";
  rockface::test::write_card(dir / "render", card, "DSC_0001.JPG", "DSC_0002.JPG");
  ASSERT_FALSE(fs::exists(card / "visit.json"));
  const fs::path project = dir / "site.rockface";
  CliRun r =
      run_rockface("replay " + card.string() + " --project " + project.string() + " --preset fast");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("base lengths: unscaled"), std::string::npos) << r.out;
  for (const char* metric : {" mm", " m2", " m3", " cm"})
    EXPECT_EQ(r.out.find(metric), std::string::npos) << metric << " in: " << r.out;

  r = run_rockface("propose " + project.string() + " --out " + (dir / "p.json").string() +
                   " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("unscaled"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find(" m2"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "p.json"));
  fs::remove_all(dir);
}

}  // namespace
