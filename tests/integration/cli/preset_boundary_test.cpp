// Every place a preset name enters the program refuses an unknown or empty
// name the same way (core/common/preset.h): exit code 2, the field named,
// the valid names listed, nothing done. The scene file, then the verbs'
// --preset.
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/temp_folders.h"

namespace {

namespace fs = std::filesystem;

using rockface::test::CliRun;
using rockface::test::run_rockface;

const std::string kValidNames = "(fast | standard | precise)";

fs::path work_dir() {
  const fs::path d =
      fs::temp_directory_path() / ("rockface-preset-boundary-" + std::to_string(::getpid()));
  fs::create_directories(d);
  rockface::test::remove_when_passed(d);
  return d;
}

std::string sample() {
  return std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/slope-wedge.scene.json";
}

// The sample scene with analysis.preset set to `name`.
std::string scene_with_preset(const std::string& name) {
  std::ifstream in(sample());
  nlohmann::json j = nlohmann::json::parse(in);
  j["analysis"]["preset"] = name;
  const fs::path p = work_dir() / ("preset-" + std::to_string(name.size()) + ".scene.json");
  std::ofstream(p) << j.dump(2);
  return p.string();
}

void expect_refused(const CliRun& r, const std::string& where, const std::string& reason) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "rockface: " + where + ": " + reason + "\n");
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(PresetBoundary, TheSceneRefusesAnUnknownOrEmptyPreset) {
  const std::string best = scene_with_preset("best");
  expect_refused(run_rockface("analyse " + best), best + ": analysis.preset",
                 "unknown preset 'best' " + kValidNames);
  const std::string empty = scene_with_preset("");
  expect_refused(run_rockface("analyse " + empty), empty + ": analysis.preset",
                 "no preset given " + kValidNames);
}

TEST(PresetBoundary, ReplayRefusesAnUnknownOrEmptyPresetBeforeAnythingIsStored) {
  const fs::path project = work_dir() / "refused.rockface";
  fs::remove(project);
  const std::string args = "replay " + sample() + " --project " + project.string() + " --preset ";
  expect_refused(run_rockface(args + "best"), "--preset", "unknown preset 'best' " + kValidNames);
  expect_refused(run_rockface(args + "''"), "--preset", "no preset given " + kValidNames);
  EXPECT_FALSE(fs::exists(project));
}

TEST(PresetBoundary, ReconstructRefusesAnUnknownPresetBeforeReadingThePair) {
  const fs::path out = work_dir() / "refused.ply";
  fs::remove(out);
  const std::string d = work_dir().string();
  expect_refused(run_rockface("reconstruct " + d + "/left.png " + d + "/right.png --camera " + d +
                              "/camera.json --preset Fast --out " + out.string()),
                 "--preset", "unknown preset 'Fast' " + kValidNames);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
