// Issue 41: points of a scene beyond any survey (a datum, a wedges origin
// or a water table's point of 1e308) were taken: the wedges came out "of
// no size", "lifts" with FoS 0, or "stable" under a water table 1e308 away,
// and their JSON carried null coordinates. Each is refused naming its field
// and the ranges (core/tunnel/survey_ranges.h), and every sample scene
// still loads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "storage/scene/scene.h"
#include "tests/support/refusal.h"
#include "tests/support/test_paths.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::refusal;

const std::string kRanges =
    "must be survey coordinates (easting and northing within +-1e+08 m, elevation within "
    "+-100000 m)";

json wedges_sample() {
  return json::parse(
      std::ifstream(fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples/tunnel-wedges.scene.json"));
}

std::string read(const json& scene) {
  return refusal([&] { rockface::storage::parse_scene(scene.dump(), "S.json"); });
}

TEST(SceneSurveyRanges, ADatumBeyondAnySurveyIsRefusedByName) {
  json s = wedges_sample();
  ASSERT_EQ(read(s), "accepted");
  s["datum"] = {1e308, 1200000.0, 450.0};
  EXPECT_EQ(read(s), "S.json: datum: " + kRanges);
  s["datum"] = {2600000.0, 1200000.0, -2e5};
  EXPECT_EQ(read(s), "S.json: datum: " + kRanges);
}

TEST(SceneSurveyRanges, AWedgesOriginBeyondAnySurveyIsRefusedByName) {
  json s = wedges_sample();
  s["wedges"]["origin"] = {1e308, 0.0, 0.0};
  EXPECT_EQ(read(s), "S.json: wedges.origin: " + kRanges);
  s["wedges"]["origin"] = {2600000.0, 1200000.0, -1e308};
  EXPECT_EQ(read(s), "S.json: wedges.origin: " + kRanges);
}

TEST(SceneSurveyRanges, AWaterTablesPointBeyondAnySurveyIsRefusedByName) {
  json s = wedges_sample();
  s["effects"]["water"]["phreatic_surface"]["point"] = {1e308, 0.0, 0.0};
  EXPECT_EQ(read(s), "S.json: effects.water.phreatic_surface.point: " + kRanges);
}

TEST(SceneSurveyRanges, TheShotcretesShearStrengthIsHeldToItsRange) {
  json s = wedges_sample();
  s["wedges"]["support"]["shotcrete"]["shear_strength"] = 1e308;
  EXPECT_EQ(read(s),
            "S.json: wedges.support.shotcrete.shear_strength: 1e+308 Pa is outside [100000, "
            "1e+07] Pa (the range of shotcrete's shear strength)");
  s["wedges"]["support"]["shotcrete"]["shear_strength"] = 1e7;
  EXPECT_EQ(read(s), "accepted");
}

TEST(SceneSurveyRanges, EverySampleSceneStillLoads) {
  int scenes = 0;
  for (const auto& e : fs::directory_iterator(fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples")) {
    const std::string name = e.path().filename().string();
    if (name.size() < 11 || name.substr(name.size() - 11) != ".scene.json") continue;
    ++scenes;
    EXPECT_EQ(refusal([&] { rockface::storage::load_scene(e.path().string()); }), "accepted")
        << name;
  }
  EXPECT_GE(scenes, 7);  // tools/samples holds seven scenes
}

}  // namespace
