// `rockface analyse` with analysis.stability = "equilibrium_path": the block
// mechanics runs, its numbers agree with limit equilibrium for rigid-plastic
// joints, the path plot is written and has a curve in it; without it no
// mechanics is computed; bad joint-law parameters are named.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;

using rockface::test::CliRun;
using rockface::test::run_rockface;

std::string scene_with(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/slope-wedge.scene.json");
  nlohmann::json j = nlohmann::json::parse(in);
  edit(j);
  const fs::path p = fs::temp_directory_path() / (name + ".scene.json");
  std::ofstream(p) << j.dump(2);
  return p.string();
}

void rigid_plastic_path(nlohmann::json& j) {
  j["analysis"]["stability"] = "equilibrium_path";
  j["effects"]["joint_law"] = {{"model", "coulomb"}, {"normal_stiffness", 1e11}};
}

TEST(AnalyseMechanicsCli, EquilibriumPathMatchesLimitEquilibriumAndPlotsThePath) {
  const std::string scene = scene_with("mechanics-path", rigid_plastic_path);
  const fs::path out = fs::temp_directory_path() / "mechanics-path.report.json";
  const fs::path png = fs::temp_directory_path() / "mechanics-path.report.B1.path.png";
  fs::remove(png);
  const CliRun r = run_rockface("analyse " + scene + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out);
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report.at("analyses"),
            nlohmann::json::array({"geometry", "limit_equilibrium", "equilibrium_path"}));
  const auto& b = report.at("blocks").at(0);
  ASSERT_TRUE(b.contains("mechanics"));
  const auto& m = b.at("mechanics");
  EXPECT_EQ(m.at("outcome"), "limit point");
  // Rigid-plastic joints (Coulomb, 1e11 Pa/m, the joints' own friction):
  // the limit point is limit equilibrium's FoS; the continuation finds it
  // from below to within its minimum step (0.05 / 64 in lambda).
  EXPECT_NEAR(m.at("fos_limit_point").get<double>(), b.at("fos").get<double>(), 0.05 / 64);
  EXPECT_EQ(m.at("failure_mode").at("kind"), "translation");
  EXPECT_EQ(m.at("stability"), "divergence");
  EXPECT_GE(m.at("path").size(), 3u);
  EXPECT_EQ(m.at("plot"), png.filename().string());
  // The plot: its curve is drawn (blue-ish pixels), not just an empty frame.
  const cv::Mat img = cv::imread(png.string());
  ASSERT_FALSE(img.empty());
  int curve = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      if (p[0] > 100 && p[2] < 80) ++curve;
    }
  EXPECT_GT(curve, 100);
}

TEST(AnalyseMechanicsCli, WithoutEquilibriumPathNoMechanicsIsComputed) {
  const std::string scene = scene_with("mechanics-none", [](nlohmann::json& j) {
    j["effects"]["joint_law"] = {{"model", "coulomb"}};
  });
  const CliRun r = run_rockface("analyse " + scene);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report.at("analyses"), nlohmann::json::array({"geometry", "limit_equilibrium"}));
  for (const auto& b : report.at("blocks")) EXPECT_FALSE(b.contains("mechanics"));
  EXPECT_NE(r.out.find("not part of limit equilibrium"), std::string::npos);
}

TEST(AnalyseMechanicsCli, BadJointLawIsNamed) {
  const std::string negative = scene_with("mechanics-negative", [](nlohmann::json& j) {
    rigid_plastic_path(j);
    j["effects"]["joint_law"]["normal_stiffness"] = -1e9;
  });
  CliRun r = run_rockface("analyse " + negative);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("effects.joint_law.normal_stiffness"), std::string::npos) << r.err;
  const std::string jrc = scene_with("mechanics-jrc", [](nlohmann::json& j) {
    rigid_plastic_path(j);
    j["effects"]["joint_law"] = {{"model", "barton_bandis"}, {"jrc", 25}};
  });
  r = run_rockface("analyse " + jrc);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("effects.joint_law.jrc"), std::string::npos) << r.err;
  const std::string density = scene_with("mechanics-density", [](nlohmann::json& j) {
    rigid_plastic_path(j);
    j["analysis"]["contact_density"] = 0;
  });
  r = run_rockface("analyse " + density);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("analysis.contact_density"), std::string::npos) << r.err;
}

TEST(AnalyseMechanicsCli, NoLimitPointIsReportedNotLooped) {
  // Strengths reduced up to lambda_max = 1.2 only, below the wedge's FoS
  // of 1.39: the path stops at the bound and says so.
  const std::string scene = scene_with("mechanics-bound", [](nlohmann::json& j) {
    rigid_plastic_path(j);
    j["analysis"]["lambda_max"] = 1.2;
  });
  const CliRun r = run_rockface("analyse " + scene);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  const auto& m = report.at("blocks").at(0).at("mechanics");
  EXPECT_EQ(m.at("outcome"), "no limit point reached");
  EXPECT_TRUE(m.at("fos_limit_point").is_null());
  EXPECT_EQ(m.at("stability"), "stable");
}

}  // namespace
