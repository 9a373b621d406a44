// The equilibrium path without effects.joint_law (issue 28): each joint is
// Coulomb with its own friction and cohesion, stiff and without dilation,
// so a sliding wedge's limit point follows limit equilibrium as its
// friction changes, and the report names the law that ran. Roughness
// (Barton-Bandis) only when the scene asks for it.
#include <filesystem>
#include <fstream>
#include <string>
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::CliRun;
using rockface::test::run_rockface;

// The slope-wedge sample turned into a cohesionless wedge of two joints
// (42/140 and 46/220, both at friction phi) under gravity alone, whose limit
// equilibrium is 0.88 at 30 degrees and 1.06 at 35: it falls at one and
// stands at the other.
nlohmann::json wedge(double phi) {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/slope-wedge.scene.json");
  nlohmann::json j = nlohmann::json::parse(in);
  j.erase("effects");
  j["joints"][0]["dip"] = 42;
  j["joints"][0]["dipdir"] = 140;
  j["joints"][1]["dip"] = 46;
  j["joints"][1]["dipdir"] = 220;
  for (auto& joint : j["joints"]) {
    joint["friction"] = phi;
    joint["cohesion"] = 0;
  }
  j["analysis"]["stability"] = "equilibrium_path";
  j["analysis"]["rotation"] = false;
  return j;
}

nlohmann::json analysed(const nlohmann::json& scene, const std::string& name) {
  const fs::path p =
      fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".scene.json");
  std::ofstream(p) << scene.dump(2);
  const CliRun r = run_rockface("analyse " + p.string());
  fs::remove(p);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

TEST(JointLawDefault, WedgeLimitPointFollowsLimitEquilibriumAtTwoFrictionAngles) {
  double fos_at[2] = {0, 0};
  int k = 0;
  for (const double phi : {30.0, 35.0}) {
    const nlohmann::json report = analysed(wedge(phi), "joint-law-default");
    ASSERT_FALSE(report.is_null());
    // No joint_law in the scene: none simulated, and the report says which law ran.
    EXPECT_EQ(report.at("effects_simulated"), nlohmann::json::array({"gravity"}));
    const auto& b = report.at("blocks").at(0);
    ASSERT_TRUE(b.contains("mechanics")) << phi;
    const auto& m = b.at("mechanics");
    EXPECT_EQ(m.at("joint_law"), "coulomb (scene friction/cohesion)");
    EXPECT_EQ(m.at("outcome"), "limit point");
    EXPECT_EQ(m.at("failure_mode").at("kind"), "translation");
    // Rigid-plastic joints (1e11 Pa/m against a wedge of tens of metres):
    // the limit point is limit equilibrium's FoS, found from below to within
    // the continuation's smallest step (0.05 / 64 in lambda).
    const double le = b.at("fos").get<double>();
    EXPECT_NEAR(m.at("fos_limit_point").get<double>(), le, 0.05 / 64) << "phi " << phi;
    fos_at[k++] = m.at("fos_limit_point").get<double>();
  }
  // The wedge that limit equilibrium drops at 30 degrees (0.88) and holds at
  // 35 (1.06): the mechanics says the same, not "3.5 times safe" for both.
  EXPECT_LT(fos_at[0], 1.0);
  EXPECT_GT(fos_at[1], 1.0);
}

TEST(JointLawDefault, RoughnessOnlyWhenTheSceneAsksForIt) {
  nlohmann::json scene = wedge(30);
  scene["effects"] = {{"joint_law", {{"model", "barton_bandis"}, {"jrc", 10}, {"jcs", 1e8}}}};
  const nlohmann::json report = analysed(scene, "joint-law-barton");
  ASSERT_FALSE(report.is_null());
  EXPECT_EQ(report.at("effects_simulated"), nlohmann::json::array({"gravity", "joint_law"}));
  const auto& b = report.at("blocks").at(0);
  ASSERT_TRUE(b.contains("mechanics"));
  EXPECT_EQ(b.at("mechanics").at("joint_law"), "barton_bandis");
  // JRC 10 adds roughness to the 30 degrees of friction: the rough joints
  // hold the wedge that the smooth ones drop.
  EXPECT_GT(b.at("mechanics").at("fos_limit_point").get<double>(), 1.0);
}

TEST(JointLawDefault, JointWithoutFrictionIsNamed) {
  nlohmann::json scene = wedge(30);
  scene["joints"][1].erase("friction");
  const nlohmann::json report = analysed(scene, "joint-law-no-friction");
  ASSERT_FALSE(report.is_null());
  const auto& b = report.at("blocks").at(0);
  ASSERT_TRUE(b.contains("mechanics"));
  bool named = false;
  for (const auto& n : b.at("notes"))
    named =
        named || n.get<std::string>().find("plane J2 has no friction angle") != std::string::npos;
  EXPECT_TRUE(named) << b.at("notes").dump();
}

}  // namespace
