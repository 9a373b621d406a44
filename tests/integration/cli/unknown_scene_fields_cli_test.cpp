// Issue 41: a misspelt key inside an object of the scene ("bond_strenght" in
// wedges.support.bolts) was ignored and gave a different factor of safety
// without a word. Every object of the scene refuses a key it does not know,
// naming its path (exit 2); the samples as they are still load.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace {

namespace fs = std::filesystem;

struct Case {
  const char* sample;  // in tools/samples
  const char* verb;
  std::function<void(nlohmann::json&)> misspell;
  const char* field;  // the path the refusal names
};

}  // namespace

TEST(UnknownSceneFieldsCli, AMisspeltKeyInAnyObjectIsRefusedByItsPath) {
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
  const std::vector<Case> cases = {
      {"tunnel-wedges.scene.json", "wedges",
       [](auto& j) {
         auto& b = j["wedges"]["support"]["bolts"];
         b["bond_strenght"] = 2e4;
       },
       "wedges.support.bolts.bond_strenght"},
      {"tunnel-wedges.scene.json", "wedges",
       [](auto& j) { j["wedges"]["support"]["shotcrete"]["thicknes"] = 0.1; },
       "wedges.support.shotcrete.thicknes"},
      {"tunnel-wedges.scene.json", "wedges",
       [](auto& j) { j["wedges"]["support"]["anchors"] = true; }, "wedges.support.anchors"},
      {"tunnel-wedges.scene.json", "wedges", [](auto& j) { j["wedges"]["axis"]["trnd"] = 10; },
       "wedges.axis.trnd"},
      {"tunnel-wedges.scene.json", "wedges",
       [](auto& j) { j["wedges"]["profile"]["crown_radus"] = 3; }, "wedges.profile.crown_radus"},
      {"tunnel-drive.scene.json", "analyse", [](auto& j) { j["tunnel"]["placement"]["ofset"] = 1; },
       "tunnel.placement.ofset"},
      {"tunnel-drive.scene.json", "analyse", [](auto& j) { j["tunnel"]["drve"] = "ascending"; },
       "tunnel.drve"},
      {"tunnel-bad-day.scene.json", "analyse",
       [](auto& j) { j["imaging"]["effects"]["dust"]["air_light"] = 0.5; },
       "imaging.effects.dust.air_light"},
      {"tunnel-bad-day.scene.json", "analyse",
       [](auto& j) { j["imaging"]["effects"]["lamps"][0]["intensty"] = 2; },
       "imaging.effects.lamps[0].intensty"},
      {"tunnel-face-demo.scene.json", "analyse",
       [](auto& j) { j["picks"]["traces"][0]["photograph"] = "left"; },
       "picks.traces[0].photograph"},
      {"slope-wedge.scene.json", "analyse", [](auto& j) { j["joints"][1]["frction"] = 30; },
       "joints[1].frction"},
      {"slope-wedge.scene.json", "analyse",
       [](auto& j) { j["analysis"]["orientation_uncertainty"] = 2; },
       "analysis.orientation_uncertainty"},
      {"slope-wedge.scene.json", "analyse",
       [](auto& j) {
         j["effects"]["seismic"]["acceleraton"] = {0, 0, 0};
       },
       "effects.seismic.acceleraton"},
      {"slope-wedge.scene.json", "analyse", [](auto& j) { j["effect"] = j["effects"]; }, "effect"},
  };
  const fs::path dir = fs::temp_directory_path() / "unknown-scene-fields-cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& entry : fs::directory_iterator(samples))
    fs::copy_file(entry.path(), dir / entry.path().filename());
  for (const auto& c : cases) {
    // As it is, the sample loads (no refusal of its own keys).
    const fs::path as_is = dir / c.sample;
    const auto ok = rockface::test::run_rockface(std::string(c.verb) + " " + as_is.string() +
                                                 " --out " + (dir / "out.json").string());
    EXPECT_EQ(ok.err.find("unknown field"), std::string::npos) << c.sample << ": " << ok.err;

    std::ifstream in(as_is);
    nlohmann::json j = nlohmann::json::parse(in);
    c.misspell(j);
    const fs::path bad = dir / (std::string("bad-") + c.sample);
    std::ofstream(bad) << j.dump(2);
    const auto r = rockface::test::run_rockface(std::string(c.verb) + " " + bad.string() +
                                                " --out " + (dir / "out.json").string());
    EXPECT_EQ(r.exit_code, 2) << c.field << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(bad.string() + ": " + c.field + ": unknown field ("), std::string::npos)
        << c.field << ": " << r.err;
  }
  fs::remove_all(dir);
}
