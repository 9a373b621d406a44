// A factor of safety at 1 (issue 40, "motion after failure"): a block at
// FoS 1 - 1e-9 is not a confident "fails, then at rest": it is flagged
// marginal, and the report and the motion's trigger say why. FoS 0.9 is not.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/analysis/scene_analysis.h"
#include "core/common/progress.h"
#include "core/common/units.h"
#include "firmware-app/analysis/scene_input.h"
#include "storage/report/report.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

// The slope-wedge sample's block (both joints with friction phi_deg, no
// cohesion, gravity only), with its motion simulated for 0.2 s when it fails.
std::string wedge_scene(double phi_deg, double uncertainty_deg) {
  char buf[2048];
  std::snprintf(
      buf, sizeof buf,
      "{ \"format\": \"rockface-scene/1\",\n"
      "  \"joints\": [\n"
      "    { \"id\": \"J1\", \"dip\": 45, \"dipdir\": 105, \"point\": [5, 5, 2], \"friction\": "
      "%.17g },\n"
      "    { \"id\": \"J2\", \"dip\": 50, \"dipdir\": 235, \"point\": [5, 5, 2], \"friction\": "
      "%.17g } ],\n"
      "  \"free_faces\": [\n"
      "    { \"id\": \"F1\", \"dip\": 70, \"dipdir\": 180, \"point\": [5, 0, 0], \"rock_side\": "
      "\"lower\" },\n"
      "    { \"id\": \"F2\", \"dip\": 0, \"dipdir\": 0, \"point\": [5, 5, 10], \"rock_side\": "
      "\"lower\" } ],\n"
      "  \"blocks\": [ { \"id\": \"B1\", \"halfspaces\": { \"J1\": \"upper\", \"J2\": \"upper\", "
      "\"F1\": \"lower\", \"F2\": \"lower\" } } ],\n"
      "  \"analysis\": { \"pyramids\": false, \"blocks\": true, \"orientation_uncertainty_deg\": "
      "%.17g,\n"
      "                \"dynamics\": { \"duration_s\": 0.2, \"sample_s\": 0.1 } } }\n",
      phi_deg, phi_deg, uncertainty_deg);
  return buf;
}

analysis::Report analyse_text(const std::string& text) {
  const storage::Scene scene = storage::parse_scene(text, "S.json");
  NoProgress progress;
  return analysis::analyse(app::analysis_input(scene), progress);
}

bool says_marginal(const std::vector<std::string>& notes) {
  for (const std::string& n : notes)
    if (n.find("marginal") != std::string::npos) return true;
  return false;
}

// The friction angle (deg) that gives the block the factor of safety `fos`:
// without cohesion the FoS is proportional to tan(phi) when both joints
// share phi.
double phi_for(double fos) {
  const double phi0 = 30;
  const analysis::Report r = analyse_text(wedge_scene(phi0, 1.0));
  const double f0 = *r.blocks.at(0).fos;
  return rad_to_deg(std::atan(std::tan(deg_to_rad(phi0)) * fos / f0));
}

TEST(FosAtOne, JustBelowOneIsMarginalAndSaysWhy) {
  for (double uncertainty : {1.0, 0.0}) {
    for (double eps : {1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
      SCOPED_TRACE("FoS 1 - " + std::to_string(eps) + ", uncertainty " +
                   std::to_string(uncertainty) + " deg");
      const analysis::Report r = analyse_text(wedge_scene(phi_for(1 - eps), uncertainty));
      ASSERT_EQ(r.blocks.size(), 1u);
      const analysis::ReportBlock& b = r.blocks[0];
      ASSERT_TRUE(b.fos.has_value());
      EXPECT_NEAR(*b.fos, 1 - eps, 1e-13);
      EXPECT_TRUE(b.fos_marginal);
      EXPECT_TRUE(says_marginal(b.notes));
      if (b.dynamics) {
        EXPECT_NE(b.dynamics->trigger.find("marginal"), std::string::npos);
      }
      const nlohmann::json j = nlohmann::json::parse(storage::report_to_json(r));
      EXPECT_EQ(j["blocks"][0].value("fos_marginal", false), true);
      EXPECT_NE(analysis::report_summary(r).find("?"), std::string::npos);
    }
  }
}

TEST(FosAtOne, ClearlyBelowOneIsNotMarginal) {
  const analysis::Report r = analyse_text(wedge_scene(phi_for(0.9), 1.0));
  ASSERT_EQ(r.blocks.size(), 1u);
  const analysis::ReportBlock& b = r.blocks[0];
  ASSERT_TRUE(b.fos.has_value());
  EXPECT_NEAR(*b.fos, 0.9, 1e-12);
  EXPECT_FALSE(b.fos_marginal);
  EXPECT_FALSE(says_marginal(b.notes));
  ASSERT_TRUE(b.dynamics.has_value());  // it fails: its motion is simulated
  EXPECT_EQ(b.dynamics->trigger.find("marginal"), std::string::npos) << b.dynamics->trigger;
  const nlohmann::json j = nlohmann::json::parse(storage::report_to_json(r));
  EXPECT_FALSE(j["blocks"][0].contains("fos_marginal"));
}

}  // namespace
}  // namespace rockface
