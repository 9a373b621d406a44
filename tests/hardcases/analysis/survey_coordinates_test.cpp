// Reports at survey coordinates (issue 40): the same block at the origin and
// at E/N 5.2e6 (with and without a datum) gives the same report vertices plus
// the offset to 0.1 mm; an unknown in the motion's output is null, not 0.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/analysis/scene_analysis.h"
#include "core/common/progress.h"
#include "firmware-app/analysis/scene_input.h"
#include "storage/report/report.h"
#include "storage/report/report_dynamics_json.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

std::string xyz(double x, double y, double z) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", x, y, z);
  return buf;
}

// The slope-wedge sample's block, `scale` times its size, moved by (e, e, 0).
std::string wedge_scene(double e, double scale, bool datum) {
  auto p = [&](double x, double y, double z) {
    return xyz(e + scale * x, e + scale * y, scale * z);
  };
  std::string s = "{ \"format\": \"rockface-scene/1\",\n";
  if (datum) s += "  \"datum\": " + xyz(e, e, 0) + ",\n";
  s += "  \"joints\": [\n"
       "    { \"id\": \"J1\", \"dip\": 45, \"dipdir\": 105, \"point\": " +
       p(5, 5, 2) +
       ", \"friction\": 32 },\n"
       "    { \"id\": \"J2\", \"dip\": 50, \"dipdir\": 235, \"point\": " +
       p(5, 5, 2) +
       ", \"friction\": 30 } ],\n"
       "  \"free_faces\": [\n"
       "    { \"id\": \"F1\", \"dip\": 70, \"dipdir\": 180, \"point\": " +
       p(5, 0, 0) +
       ", \"rock_side\": \"lower\" },\n"
       "    { \"id\": \"F2\", \"dip\": 0, \"dipdir\": 0, \"point\": " +
       p(5, 5, 10) +
       ", \"rock_side\": \"lower\" } ],\n"
       "  \"blocks\": [ { \"id\": \"B1\", \"halfspaces\": { \"J1\": \"upper\", \"J2\": \"upper\", "
       "\"F1\": \"lower\", \"F2\": \"lower\" } } ],\n"
       "  \"analysis\": { \"pyramids\": false, \"blocks\": true } }\n";
  return s;
}

nlohmann::json report_json(const std::string& scene_text) {
  const storage::Scene scene = storage::parse_scene(scene_text, "S.json");
  NoProgress progress;
  const analysis::Report r = analysis::analyse(app::analysis_input(scene), progress);
  return nlohmann::json::parse(storage::report_to_json(r));
}

void expect_same_block_moved(const nlohmann::json& at_origin, const nlohmann::json& moved,
                             double e) {
  const nlohmann::json& a = at_origin["blocks"][0];
  const nlohmann::json& b = moved["blocks"][0];
  ASSERT_EQ(a["vertices"].size(), b["vertices"].size());
  ASSERT_GE(a["vertices"].size(), 4u);
  const double offset[3] = {e, e, 0};
  for (size_t v = 0; v < a["vertices"].size(); ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(b["vertices"][v][k].get<double>(), a["vertices"][v][k].get<double>() + offset[k],
                  1e-4)
          << "vertex " << v << " coordinate " << k;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(b["centroid"][k].get<double>(), a["centroid"][k].get<double>() + offset[k], 1e-4);
}

TEST(SurveyCoordinatesReport, VerticesKeepTheirTenthOfAMillimetreAtFiveMillionMetres) {
  const double e = 5.2e6;
  for (double scale : {1.0, 1e-3}) {  // the sample's wedge, and the same 1000 times smaller
    SCOPED_TRACE("scale " + std::to_string(scale));
    const nlohmann::json origin = report_json(wedge_scene(0, scale, false));
    expect_same_block_moved(origin, report_json(wedge_scene(e, scale, false)), e);
    expect_same_block_moved(origin, report_json(wedge_scene(e, scale, true)), e);
  }
}

TEST(SurveyCoordinatesReport, AnUnknownInTheMotionIsNullNotZero) {
  analysis::ReportDynamics d;
  d.trigger = "test";
  analysis::ReportMotionSample s;
  s.position = {5.2e6 + 0.12345, 5.2e6, std::numeric_limits<double>::quiet_NaN()};
  s.work = std::numeric_limits<double>::quiet_NaN();
  d.path.push_back(s);
  analysis::ReportLanding l;
  l.speed = std::numeric_limits<double>::quiet_NaN();
  l.point = {5.2e6 + 0.00012, 1, 2};
  d.landing = l;
  // As written: an unknown is null in the text.
  const nlohmann::json j = nlohmann::json::parse(storage::dynamics_to_json(d).dump());
  EXPECT_TRUE(j["path"][0]["position"][2].is_null()) << j["path"][0].dump();
  EXPECT_TRUE(j["path"][0]["energy"]["work"].is_null()) << j["path"][0].dump();
  EXPECT_TRUE(j["landing"]["speed"].is_null()) << j["landing"].dump();
  EXPECT_NEAR(j["path"][0]["position"][0].get<double>(), 5.2e6 + 0.12345, 1e-5);
  EXPECT_NEAR(j["landing"]["point"][0].get<double>(), 5.2e6 + 0.00012, 1e-5);

  // Read back from a stored block, the unknown stays unknown.
  nlohmann::ordered_json block;
  block["dynamics"] = j;
  const auto back = storage::dynamics_from_block_json(block.dump());
  ASSERT_TRUE(back.has_value());
  ASSERT_TRUE(back->landing.has_value());
  EXPECT_TRUE(std::isnan(back->landing->speed));
  ASSERT_EQ(back->path.size(), 1u);
  EXPECT_TRUE(std::isnan(back->path[0].position.z()));
  EXPECT_TRUE(std::isnan(back->path[0].work));
}

}  // namespace
}  // namespace rockface
