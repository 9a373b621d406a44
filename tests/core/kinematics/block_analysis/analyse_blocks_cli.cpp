// `rockface analyse` reporting explicit scene blocks: a plane failure with a
// tension crack, water and a bolt at survey coordinates (checked against
// Hoek & Bray's closed form), a non-convex block given by faces, and bad
// input.
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/temp_folders.h"
#include "tests/support/test_paths.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

fs::path work_dir() {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-blocks-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  rockface::test::remove_when_passed(dir);
  return dir;
}

CliRun analyse(const json& scene, const std::string& name) {
  const fs::path dir = work_dir();
  const fs::path scene_path = dir / (name + ".scene.json");
  std::ofstream(scene_path) << scene.dump(2);
  const std::string cmd = std::string(ROCKFACE_BINARY_DIR) + "/rockface analyse " +
                          scene_path.string() + " --out " + (dir / "report.json").string() + " >" +
                          (dir / "out.txt").string() + " 2>" + (dir / "err.txt").string();
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = r.exit_code == 0 ? slurp(dir / "report.json") : "";
  r.err = slurp(dir / "err.txt");
  fs::remove(dir / "report.json");
  return r;
}

double rad(double deg) {
  return deg * std::numbers::pi / 180;
}

const double D[3] = {512340.0, 5211870.0, 410.0};  // survey datum
json at(double x, double y, double z) {
  return json::array({D[0] + x, D[1] + y, D[2] + z});
}

// Hoek & Bray's plane failure (see limit_equilibrium_test.cpp): H = 20,
// face 60, plane 30, crack 6 m deep with 4 m of water, bolt 50 kN/m at 40
// degrees to the plane's normal, c = 10 kPa, phi = 35, width 5 m.
constexpr double H = 20, psi_f = 60, psi_p = 30, zc = 6, zw = 4, w = 5, T = 50e3, theta = 40;
constexpr double c = 10e3, phi = 35, rho = 2600, g = 9.81, gw = 9810;

json plane_failure_scene() {
  const double crack_y = (H - zc) / std::tan(rad(psi_p));
  json s;
  s["format"] = "rockface-scene/1";
  s["datum"] = at(0, 0, 0);
  s["rock"] = {{"density", rho}};
  s["joints"] = json::array({{{"id", "P"},
                              {"dip", psi_p},
                              {"dipdir", 180},
                              {"point", at(0, 0, 0)},
                              {"friction", phi},
                              {"cohesion", c}},
                             {{"id", "C"},
                              {"dip", 90},
                              {"dipdir", 180},
                              {"point", at(0, crack_y, H)},
                              {"friction", phi},
                              {"cohesion", 0}}});
  s["free_faces"] = json::array(
      {{{"id", "F"},
        {"dip", psi_f},
        {"dipdir", 180},
        {"point", at(0, 0, 0)},
        {"rock_side", "lower"}},
       {{"id", "U"}, {"dip", 0}, {"dipdir", 0}, {"point", at(0, 0, H)}, {"rock_side", "lower"}},
       {{"id", "L0"}, {"dip", 90}, {"dipdir", 90}, {"point", at(0, 0, 0)}, {"rock_side", "upper"}},
       {{"id", "L1"},
        {"dip", 90},
        {"dipdir", 90},
        {"point", at(w, 0, 0)},
        {"rock_side", "lower"}}});
  s["blocks"] = json::array({{{"id", "B1"},
                              {"halfspaces",
                               {{"P", "upper"},
                                {"C", "upper"},
                                {"F", "lower"},
                                {"U", "lower"},
                                {"L0", "upper"},
                                {"L1", "lower"}}}}});
  // Phreatic plane through the toe and the water level in the crack.
  const double phreatic_dip = std::atan((H - zc + zw) / crack_y) * 180 / std::numbers::pi;
  s["effects"]["water"] = {
      {"unit_weight", gw},
      {"phreatic_surface", {{"point", at(0, 0, 0)}, {"dip", phreatic_dip}, {"dipdir", 180}}},
      {"joints", {"P", "C"}}};
  s["effects"]["bolts"] = json::array({{{"point", at(w / 2, 0.5 * H / std::tan(rad(psi_f)), H / 2)},
                                        {"trend", 0},
                                        {"plunge", 90 - (psi_p + theta)},
                                        {"force", T * w}}});
  s["analysis"] = {{"pyramids", false}, {"rotation", false}};
  return s;
}

// Report numbers are rounded to 1e-9 relative (storage/report/report_json.cpp);
// the analysis itself agrees with the closed forms to ~1e-12.
constexpr double kReport = 1e-8;

TEST(AnalyseBlocksCli, PlaneFailureMatchesHoekAndBray) {
  const CliRun r = analyse(plane_failure_scene(), "plane-failure");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json rep = json::parse(r.out);
  EXPECT_EQ(rep["effects_simulated"], json({"gravity", "water", "bolts"}));
  ASSERT_EQ(rep["blocks"].size(), 1u);
  const json& b = rep["blocks"][0];
  EXPECT_EQ(b["id"], "B1");
  EXPECT_EQ(b["source"], "scene");
  EXPECT_EQ(b["code"], "001101");  // P C | F U L0 L1
  EXPECT_EQ(b["convex"], true);
  EXPECT_EQ(b["finite"], true);
  EXPECT_EQ(b["removable"], true);
  EXPECT_EQ(b["marginal"], false);
  EXPECT_GT(b["margin_deg"].get<double>(), 1.0);
  EXPECT_EQ(b["mode"]["type"], "sliding");
  EXPECT_EQ(b["mode"]["planes"], json({"P"}));

  const double sp = std::sin(rad(psi_p)), cp = std::cos(rad(psi_p));
  const double W = 0.5 * rho * g * H * H *
                   ((1 - (zc / H) * (zc / H)) / std::tan(rad(psi_p)) - 1 / std::tan(rad(psi_f)));
  const double A = (H - zc) / sp, U = 0.5 * gw * zw * (H - zc) / sp, V = 0.5 * gw * zw * zw;
  const double fos =
      (c * A + (W * cp - U - V * sp + T * std::cos(rad(theta))) * std::tan(rad(phi))) /
      (W * sp + V * cp - T * std::sin(rad(theta)));
  EXPECT_NEAR(b["fos"].get<double>(), fos, fos * kReport);
  EXPECT_NEAR(b["mass"].get<double>(), W * w / g, W * w / g * kReport);
  EXPECT_NEAR(b["volume"].get<double>(), W * w / g / rho, W * w / g / rho * kReport);
  EXPECT_NEAR(b["face_areas"]["P"].get<double>(), A * w, A * w * kReport);
  // Absolute coordinates: the toe corner is at the datum.
  bool toe = false;
  for (const auto& v : b["vertices"])
    toe |= std::abs(v[0].get<double>() - D[0]) < 1e-6 &&
           std::abs(v[1].get<double>() - D[1]) < 1e-6 && std::abs(v[2].get<double>() - D[2]) < 1e-6;
  EXPECT_TRUE(toe);
  EXPECT_NEAR(b["centroid"][0].get<double>(), D[0] + w / 2, 1e-6);
  EXPECT_EQ(b["inertia"].size(), 3u);
  EXPECT_EQ(b["principal_moments"].size(), 3u);
}

TEST(AnalyseBlocksCli, NonConvexBlockByFacesIsReported) {
  // An L-shaped slab on a joint (bottom), free everywhere else.
  json s = plane_failure_scene();
  s.erase("effects");
  s["joints"] = json::array({{{"id", "J"}, {"dip", 0}, {"dipdir", 0}, {"friction", 30}}});
  s["free_faces"] = json::array();
  const char* names[] = {"T", "S0", "S1", "S2", "S3", "S4", "S5"};
  const double dips[][2] = {{0, 0}, {90, 180}, {90, 90}, {90, 0}, {90, 90}, {90, 0}, {90, 270}};
  for (int k = 0; k < 7; ++k)
    s["free_faces"].push_back({{"id", names[k]},
                               {"dip", dips[k][0]},
                               {"dipdir", dips[k][1]},
                               {"rock_side", "lower"}});  // normals point out of the block
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  json verts = json::array();
  for (double z : {0.0, 1.0})
    for (const auto& p : xy) verts.push_back(at(p[0], p[1], z));
  json faces = json::array({{{"plane", "J"}, {"loop", {5, 4, 3, 2, 1, 0}}},
                            {{"plane", "T"}, {"loop", {6, 7, 8, 9, 10, 11}}}});
  for (int k = 0; k < 6; ++k)
    faces.push_back({{"plane", names[k + 1]}, {"loop", {k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k}}});
  s["blocks"] = json::array({{{"id", "L"}, {"vertices", verts}, {"faces", faces}}});
  const CliRun r = analyse(s, "l-block");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json b = json::parse(r.out)["blocks"][0];
  EXPECT_EQ(b["convex"], false);
  EXPECT_NEAR(b["volume"].get<double>(), 3.0, 3.0 * kReport);
  EXPECT_EQ(b["vertices"].size(), 12u);
  EXPECT_EQ(b["finite"], true);
  EXPECT_EQ(b["removable"], true);
  EXPECT_EQ(b["mode"]["type"], "none");  // resting on a horizontal joint
  EXPECT_EQ(b["code"].get<std::string>().size(), 8u);
  EXPECT_EQ(b["code"].get<std::string>()[0], '0');  // above J
}

TEST(AnalyseBlocksCli, HalfSpaceBlockNeedsPlanePoints) {
  json s = plane_failure_scene();
  s["joints"][1].erase("point");
  const CliRun r = analyse(s, "no-point");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("joints[1].point"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("B1"), std::string::npos) << r.err;
}

TEST(AnalyseBlocksCli, OpenBlockByFacesIsBadInput) {
  json s = plane_failure_scene();
  s.erase("effects");
  const json v = json::array({at(0, 0, 0), at(1, 0, 0), at(0, 1, 0), at(0, 0, 1)});
  s["blocks"] = json::array({{{"id", "T"},
                              {"vertices", v},
                              {"faces", json::array({{{"plane", "P"}, {"loop", {0, 2, 1}}},
                                                     {{"plane", "C"}, {"loop", {0, 1, 3}}},
                                                     {{"plane", "F"}, {"loop", {0, 3, 2}}}})}}});
  const CliRun r = analyse(s, "open");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("blocks[0]"), std::string::npos) << r.err;
}

TEST(AnalyseBlocksCli, InfiniteHalfSpaceBlockIsReportedNotAnError) {
  json s = plane_failure_scene();
  s["blocks"][0]["halfspaces"].erase("P");  // no sliding plane: open downward into the rock
  const CliRun r = analyse(s, "infinite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json b = json::parse(r.out)["blocks"][0];
  EXPECT_EQ(b["finite"], false);
  EXPECT_EQ(b["removable"], false);
  EXPECT_EQ(b["code"], "201101");  // P not involved
  EXPECT_FALSE(b.contains("volume"));
}

}  // namespace
