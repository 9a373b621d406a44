// A block that falls in a tunnel lands on the invert: a scene that asks for
// analysis.dynamics with no floor, inside a tunnel, gets the invert at its
// face as the floor.
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "firmware-app/analysis/scene_input.h"
#include "storage/scene/scene.h"
#include "tests/support/test_paths.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(TunnelInvertFloor, DynamicsWithoutAFloorLandsOnTheInvertAtTheFace) {
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
  json doc = {{"format", "rockface-scene/1"},
              {"datum", {512340.0, 5211870.0, 410.0}},
              {"analysis", {{"dynamics", {{"duration_s", 2.0}}}}},
              {"tunnel",
               {{"alignment", (samples / "tunnel-drive.alignment.csv").string()},
                {"profile", (samples / "tunnel-drive.profile.json").string()},
                {"placement", {{"chainage", 110.6}, {"offset", 1.3}, {"height", -1.05}}}}}};
  const analysis::AnalysisInput in =
      analysis_input(storage::parse_scene(doc.dump(), "t.scene.json"));
  ASSERT_TRUE(in.analysis.dynamics);
  ASSERT_TRUE(in.analysis.dynamics->floor);
  const auto& f = *in.analysis.dynamics->floor;
  // The sample's alignment runs level due north at 410.0 m; the horseshoe's
  // invert is 1.5 m below the axis (sampled every centimetre of outline: the
  // invert is a straight line, so its lowest point is exact).
  EXPECT_NEAR(f.point.z(), 408.5, 1e-9);
  EXPECT_NEAR(f.point.y(), 5211800.0 + 110.6, 1e-6);
  EXPECT_NEAR(f.dip, 0.0, 1e-9);
  // A floor the scene gives is kept.
  doc["analysis"]["dynamics"]["floor"] = {{"elevation", 400.0}};
  const analysis::AnalysisInput given =
      analysis_input(storage::parse_scene(doc.dump(), "t.scene.json"));
  EXPECT_NEAR(given.analysis.dynamics->floor->point.z(), 400.0, 1e-12);
}

}  // namespace
}  // namespace rockface::app
