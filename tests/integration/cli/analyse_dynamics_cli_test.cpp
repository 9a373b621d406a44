// `rockface analyse` with analysis.dynamics: the failing wedge's motion is
// in the report (events, sampled path, energies, landing), the effects
// list it, the picture beside the report has outlines in it; without
// analysis.dynamics nothing of it is computed; bad fields are named.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace {

namespace fs = std::filesystem;

using rockface::test::CliRun;
using rockface::test::run_rockface;

std::string sample_with(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) +
                   "/tools/samples/slope-wedge-dynamics.scene.json");
  nlohmann::json j = nlohmann::json::parse(in);
  edit(j);
  const fs::path p = fs::temp_directory_path() / (name + ".scene.json");
  std::ofstream(p) << j.dump(2);
  return p.string();
}

TEST(AnalyseDynamicsCli, FailingWedgeMovesLandsAndIsPictured) {
  const std::string scene = sample_with("dynamics-wedge", [](nlohmann::json&) {});
  const fs::path out = fs::temp_directory_path() / "dynamics-wedge.report.json";
  const fs::path png = fs::temp_directory_path() / "dynamics-wedge.report.B1.dynamics.png";
  fs::remove(png);
  const CliRun r = run_rockface("analyse " + scene + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out);
  const nlohmann::json report = nlohmann::json::parse(in);
  const auto& effects = report.at("effects_simulated");
  EXPECT_NE(std::find(effects.begin(), effects.end(), "dynamics after failure"), effects.end());
  const auto& b = report.at("blocks").at(0);
  ASSERT_LT(b.at("fos").get<double>(), 1.0);
  ASSERT_TRUE(b.contains("dynamics"));
  const auto& d = b.at("dynamics");
  EXPECT_EQ(d.at("events").at(0).at("event"), "slides on J1 and J2");
  EXPECT_EQ(d.at("events").back().at("kind"), "lands");
  EXPECT_EQ(d.at("outcome"), "lands");
  // Samples every 0.5 s until the landing, each with a unit quaternion.
  ASSERT_GE(d.at("path").size(), 10u);
  for (const auto& s : d.at("path")) {
    const auto& q = s.at("orientation");
    const double n = std::hypot(std::hypot(q[0].get<double>(), q[1].get<double>()),
                                std::hypot(q[2].get<double>(), q[3].get<double>()));
    EXPECT_NEAR(n, 1.0, 1e-8);  // written with 9 digits
  }
  const auto& l = d.at("landing");
  // The floor is at elevation 404 m: the landing corner is on it (9 digits
  // of 4e2 m written: 1e-6 m).
  EXPECT_NEAR(l.at("point").at(2).get<double>(), 404.0, 1e-5);
  EXPECT_GT(l.at("speed").get<double>(), 0.0);
  EXPECT_GT(l.at("kinetic_energy").get<double>(), 0.0);
  EXPECT_LE(d.at("numerics").at("drift_after_m").get<double>(),
            d.at("numerics").at("drift_bound_m").get<double>());
  EXPECT_EQ(d.at("picture"), png.filename().string());
  // The picture: outlines in colour (blue to red), not an empty frame.
  const cv::Mat img = cv::imread(png.string());
  ASSERT_FALSE(img.empty());
  int ink = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      if (std::abs(p[0] - p[2]) > 60) ++ink;
    }
  EXPECT_GT(ink, 2000);
}

TEST(AnalyseDynamicsCli, WithoutAnalysisDynamicsNothingIsComputed) {
  const std::string scene =
      sample_with("dynamics-none", [](nlohmann::json& j) { j["analysis"].erase("dynamics"); });
  const CliRun r = run_rockface("analyse " + scene);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  const auto& effects = report.at("effects_simulated");
  EXPECT_EQ(std::find(effects.begin(), effects.end(), "dynamics after failure"), effects.end());
  ASSERT_LT(report.at("blocks").at(0).at("fos").get<double>(), 1.0);  // it would fail
  EXPECT_FALSE(report.at("blocks").at(0).contains("dynamics"));
}

TEST(AnalyseDynamicsCli, BadFieldsAreNamed) {
  const std::string unknown = sample_with(
      "dynamics-bad", [](nlohmann::json& j) { j["analysis"]["dynamics"]["duraton_s"] = 2; });
  CliRun r = run_rockface("analyse " + unknown);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("analysis.dynamics.duraton_s"), std::string::npos) << r.err;
  const std::string negative = sample_with(
      "dynamics-neg", [](nlohmann::json& j) { j["analysis"]["dynamics"]["sample_s"] = -1; });
  r = run_rockface("analyse " + negative);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("analysis.dynamics.sample_s"), std::string::npos) << r.err;
  const std::string floor = sample_with("dynamics-floor", [](nlohmann::json& j) {
    j["analysis"]["dynamics"]["floor"] = {{"elevation", 404}, {"point", {0, 0, 0}}};
  });
  r = run_rockface("analyse " + floor);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("analysis.dynamics.floor"), std::string::npos) << r.err;
  const std::string effect = sample_with("dynamics-effect", [](nlohmann::json& j) {
    j["effects"]["dynamics"] = {{"duration_s", 2}};
  });
  r = run_rockface("analyse " + effect);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("effects.dynamics"), std::string::npos) << r.err;
}

}  // namespace

namespace {

// With the equilibrium path, a block that holds (FoS 1.39) is set moving
// from its limit point: its joints' friction reduced by the limit point's
// lambda (tan phi / lambda), cohesion lost.
TEST(AnalyseDynamicsCli, FromTheLimitPointOfTheEquilibriumPath) {
  const std::string scene = sample_with("dynamics-limit", [](nlohmann::json& j) {
    j["joints"][0]["friction"] = 32;
    j["joints"][1]["friction"] = 30;
    j["analysis"]["stability"] = "equilibrium_path";
    j["effects"]["joint_law"] = {{"model", "coulomb"}, {"normal_stiffness", 1e11}};
  });
  const CliRun r = run_rockface("analyse " + scene);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  const auto& b = report.at("blocks").at(0);
  ASSERT_GT(b.at("fos").get<double>(), 1.0);  // limit equilibrium: it holds
  const double lambda = b.at("mechanics").at("fos_limit_point").get<double>();
  ASSERT_TRUE(b.contains("dynamics"));
  const auto& d = b.at("dynamics");
  EXPECT_EQ(d.at("trigger").get<std::string>().rfind("equilibrium path: from its limit point", 0),
            0u);
  // Written with 9 significant digits.
  EXPECT_NEAR(d.at("strength_divisor").get<double>(), lambda, 1e-8 * lambda);
  const double j1 = std::atan(std::tan(32 * M_PI / 180) / lambda) * 180 / M_PI;
  EXPECT_NEAR(d.at("friction_deg").at("J1").get<double>(), j1, 1e-6);
}

}  // namespace
