// The wedges JSON at survey coordinates (issue 40): the tunnel-wedges
// sample moved to E/N 5.2e6 with no datum writes each wedge's vertices,
// apex and bolt heads to 0.1 mm of the computed points (they were written
// to 1 mm, which at 5.2e6 m is all a survey's precision leaves of a small
// wedge's corners), and no survey coordinate as a rounding artefact.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "firmware-app/wedges/wedge_input.h"
#include "firmware-app/wedges/wedges_json.h"
#include "storage/scene/scene.h"
#include "tests/support/test_paths.h"

namespace rockface {
namespace {

std::string sample_moved_far() {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-wedges.scene.json");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  // No datum: the sample's positions become E/N 5.2e6.
  const std::string datum = "\"datum\": [2600000.0, 1200000.0, 450.0],";
  s.erase(s.find(datum), datum.size());
  for (std::size_t at; (at = s.find("2600000.0, 1200000.0")) != std::string::npos;)
    s.replace(at, 20, "5200000.0, 5200000.0");
  return s;
}

// Half the 0.1 mm step, plus the spacing of doubles at 5.2e6 m (1e-9 m).
constexpr double kWithin = 0.5e-4 + 1e-9;

void expect_point(const nlohmann::json& j, const Eigen::Vector3d& p, const std::string& what) {
  ASSERT_TRUE(j.is_array() && j.size() == 3) << what;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(j[k].get<double>(), p[k], kWithin) << what << " [" << k << "]";
}

TEST(WedgesJsonSurveyCoordinates, PointsAreWrittenToATenthOfAMillimetre) {
  const storage::Scene scene = storage::parse_scene(sample_moved_far(), "far.json");
  const app::WedgeRun run = app::wedge_run_from_scene(scene);
  const tunnel::WedgeAnalysis a = app::run_wedges(run);
  ASSERT_EQ(a.wedges.size(), 7u);
  const nlohmann::json j = nlohmann::json::parse(app::wedges_json(run, a));
  ASSERT_EQ(j["wedges"].size(), a.wedges.size());
  int bolts = 0;
  for (std::size_t i = 0; i < a.wedges.size(); ++i) {
    const tunnel::Wedge& w = a.wedges[i];
    const nlohmann::json& jw = j["wedges"][i];
    ASSERT_GT(w.apex.x(), 5e6);
    expect_point(jw["apex"], w.apex, w.code + " apex");
    ASSERT_EQ(jw["vertices"].size(), w.block.vertices().size());
    for (std::size_t v = 0; v < w.block.vertices().size(); ++v)
      expect_point(jw["vertices"][v], w.block.absolute_vertex(static_cast<int>(v)),
                   w.code + " vertex " + std::to_string(v));
    if (!jw.contains("bolts")) continue;
    for (std::size_t b = 0; b < w.bolts.size(); ++b, ++bolts)
      expect_point(jw["bolts"]["list"][b]["head"], w.bolts[b].head,
                   w.code + " bolt " + std::to_string(b));
  }
  EXPECT_GT(bolts, 0);
}

}  // namespace
}  // namespace rockface
