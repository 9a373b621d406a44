// `rockface analyse` as a user runs it: the real binary, real files.
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/test_paths.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;

using rockface::test::CliRun;
using rockface::test::run_rockface;

std::string sample() {
  return std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/slope-wedge.scene.json";
}

// Writes a scene built from the sample with one edit applied to its JSON.
std::string scene_with(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  std::ifstream in(sample());
  nlohmann::json j = nlohmann::json::parse(in);
  edit(j);
  const fs::path p = fs::temp_directory_path() / (name + ".scene.json");
  std::ofstream(p) << j.dump(2);
  return p.string();
}

TEST(AnalyseCli, ReportHasTheFieldsOfSceneMd) {
  const CliRun r = run_rockface("analyse " + sample());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report.at("format"), "rockface-report/1");
  EXPECT_EQ(report.at("effects_simulated"), nlohmann::json::array({"gravity", "seismic"}));
  const auto& pyramids = report.at("pyramids");
  // 3 joints, one face group: 2^3 codes.
  ASSERT_EQ(pyramids.size(), 8u);
  int removable = 0;
  for (const auto& p : pyramids) {
    for (const char* key :
         {"face", "code", "empty", "finite", "removable", "margin_deg", "marginal"})
      EXPECT_TRUE(p.contains(key)) << key;
    EXPECT_EQ(p.at("code").get<std::string>().size(), 3u);
    if (p.at("removable").get<bool>()) {
      ++removable;
      ASSERT_TRUE(p.contains("mode"));
      EXPECT_TRUE(p.at("mode").contains("type"));
      EXPECT_TRUE(p.at("mode").contains("planes"));
      EXPECT_TRUE(p.contains("fos"));
    }
  }
  EXPECT_GT(removable, 0);
  EXPECT_TRUE(report.at("timings_ms").contains("pyramids"));
  // The wedge B1 between J1, J2 and the cut: a finite polyhedron with its
  // mass properties, the same sliding mode as its pyramid, and rotation.
  const auto& blocks = report.at("blocks");
  ASSERT_EQ(blocks.size(), 1u);
  const auto& b = blocks[0];
  for (const char* key :
       {"id", "source", "code", "convex", "vertices", "volume", "mass", "centroid", "inertia",
        "principal_moments", "face_areas", "finite", "removable", "margin_deg", "marginal", "mode",
        "fos", "rotation", "remote_axis"})
    EXPECT_TRUE(b.contains(key)) << key;
  EXPECT_EQ(b.at("code"), "00211");
  EXPECT_TRUE(b.at("removable").get<bool>());
  EXPECT_EQ(b.at("mode").at("planes"), nlohmann::json::array({"J1", "J2"}));
  EXPECT_FALSE(b.at("rotation").at("corners").empty());
  // B1 rotates about a corner, so it has an axis and the remote-axis search
  // (16 starts in the scene) is skipped (issue 17): found, no starts, a note.
  EXPECT_TRUE(b.at("remote_axis").at("found").get<bool>());
  EXPECT_EQ(b.at("remote_axis").at("starts"), 0);
  bool skipped_note = false;
  for (const auto& n : b.at("notes"))
    skipped_note = skipped_note || n.get<std::string>().find("not searched") != std::string::npos;
  EXPECT_TRUE(skipped_note);
  // Weight plus the scene's seismic load (0, -0.98, 0) m/s^2, both acting
  // at the centroid: force = mass x (0, -0.98, -9.81), no moment. The report
  // rounds to 9 significant digits (tidy), so 1e-8 relative.
  const double m = b.at("mass").get<double>();
  const auto& force = b.at("resultant").at("force");
  const double expected[3] = {0, -0.98 * m, -9.81 * m};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(force[k].get<double>(), expected[k], 1e-8 * 9.81 * m);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(b.at("resultant").at("moment")[k].get<double>(), 0, 1e-8 * 9.81 * m);
}

TEST(AnalyseCli, OutWritesTheFileAndSummaryPrintsATable) {
  const fs::path out = fs::temp_directory_path() / "rockface-cli-report.json";
  fs::remove(out);
  const CliRun r = run_rockface("analyse " + sample() + " --out " + out.string() + " --summary");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream f(out);
  const nlohmann::json report = nlohmann::json::parse(f);
  EXPECT_EQ(report.at("format"), "rockface-report/1");
  EXPECT_NE(r.out.find("removable"), std::string::npos);
  EXPECT_NE(r.out.find("sliding on J1+J2"), std::string::npos) << r.out;
}

struct BadScene {
  const char* name;
  std::function<void(nlohmann::json&)> edit;
  const char* field;  // what the message must name
};

TEST(AnalyseCli, BadScenesExitTwoNamingFileAndField) {
  const std::vector<BadScene> cases{
      {"missing-dip", [](nlohmann::json& j) { j["joints"][1].erase("dip"); }, "joints[1].dip"},
      {"dip-95", [](nlohmann::json& j) { j["joints"][0]["dip"] = 95; }, "joints[0].dip"},
      {"dip-text", [](nlohmann::json& j) { j["joints"][2]["dip"] = "steep"; }, "joints[2].dip"},
      {"duplicate-id", [](nlohmann::json& j) { j["joints"][2]["id"] = "J1"; }, "joints[2].id"},
      {"face-dup-of-joint", [](nlohmann::json& j) { j["free_faces"][0]["id"] = "J2"; },
       "free_faces[0].id"},
      {"unknown-plane",
       [](nlohmann::json& j) {
         j["blocks"] = {{{"id", "B1"}, {"halfspaces", {{"J9", "upper"}}}}};
       },
       "blocks[0].halfspaces.J9"},
      {"bad-side", [](nlohmann::json& j) { j["free_faces"][1]["rock_side"] = "below"; },
       "free_faces[1].rock_side"},
      {"bad-format", [](nlohmann::json& j) { j["format"] = "rockface-scene/9"; }, "format"},
      {"missing-format", [](nlohmann::json& j) { j.erase("format"); }, "format"},
  };
  for (const auto& c : cases) {
    const std::string path = scene_with(c.name, c.edit);
    const CliRun r = run_rockface("analyse " + path);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(path), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.field), std::string::npos) << c.name << ": " << r.err;
    // One clear line.
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.name;
  }
}

TEST(AnalyseCli, BrokenJsonAndMissingFile) {
  const fs::path p = fs::temp_directory_path() / "broken.scene.json";
  std::ofstream(p) << "{ \"format\": \"rockface-scene/1\", \"joints\": [ {\"id\": \"J1\", ";
  CliRun r = run_rockface("analyse " + p.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(p.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not valid JSON"), std::string::npos) << r.err;
  r = run_rockface("analyse /nonexistent/none.scene.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/nonexistent/none.scene.json"), std::string::npos) << r.err;
}

TEST(AnalyseCli, UsageErrorsAndHelp) {
  EXPECT_EQ(run_rockface("analyse").exit_code, 2);
  EXPECT_EQ(run_rockface("analyse --no-such-flag x").exit_code, 2);
  const CliRun help = run_rockface("analyse --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--summary"), std::string::npos);
}

TEST(AnalyseCli, UnwritableOutIsAnErrorAndLeavesNothingBehind) {
  const CliRun r = run_rockface("analyse " + sample() + " --out /nonexistent-dir/report.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("/nonexistent-dir/report.json"), std::string::npos) << r.err;
}

}  // namespace
