// A scene's survey precision (analysis.survey_precision_m, issue 40) through
// the whole analysis: block W has four to six joints through one vertex,
// their points moved as a survey gives them. Moved below the precision
// (1e-8 to 1e-6 m against 0.1 mm) W is the exact pyramid's shape, one apex,
// and says which planes were taken through it; moved above it (1 to 10 mm)
// the analysis still reports every block, never aborts. Outside 1e-6..1 m
// the field is refused by name.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/analysis/report.h"
#include "core/analysis/scene_analysis.h"
#include "core/common/error.h"
#include "core/common/progress.h"
#include "firmware-app/analysis/scene_input.h"
#include "storage/report/report.h"
#include "storage/scene/scene.h"

namespace rockface {
namespace {

struct Joint {
  double dip, dipdir;
  Eigen::Vector3d point;
};

// W below every joint, above the free face z = 0 (a roof); V below the
// first three joints only, above the free face (a second block, bounded or
// not, that must be reported beside W).
nlohmann::json pyramid_scene(const std::vector<Joint>& joints, double precision) {
  nlohmann::json s;
  s["format"] = "rockface-scene/1";
  s["rock"] = {{"density", 2650}};
  nlohmann::json w, v;
  for (size_t k = 0; k < joints.size(); ++k) {
    const std::string id = "J" + std::to_string(k + 1);
    const auto& p = joints[k].point;
    s["joints"].push_back({{"id", id},
                           {"dip", joints[k].dip},
                           {"dipdir", joints[k].dipdir},
                           {"point", {p.x(), p.y(), p.z()}},
                           {"friction", 30}});
    w[id] = "lower";
    if (k < 3) v[id] = "lower";
  }
  s["free_faces"].push_back(
      {{"id", "F1"}, {"dip", 0}, {"dipdir", 0}, {"point", {0, 0, 0}}, {"rock_side", "upper"}});
  w["F1"] = "upper";
  v["F1"] = "upper";
  s["blocks"].push_back({{"id", "W"}, {"halfspaces", w}});
  s["blocks"].push_back({{"id", "V"}, {"halfspaces", v}});
  s["analysis"] = {
      {"pyramids", false}, {"blocks", true}, {"rotation", true}, {"survey_precision_m", precision}};
  return s;
}

analysis::Report analyse_json(const nlohmann::json& scene) {
  const storage::Scene parsed = storage::parse_scene(scene.dump(2), "W.scene.json");
  NoProgress progress;
  return analysis::analyse(app::analysis_input(parsed), progress);
}

std::vector<Joint> random_joints(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const Eigen::Vector3d apex(100 * u(rng), 100 * u(rng), 4 + u(rng));
  const int m = 4 + static_cast<int>(3 * u(rng));
  const double turn = 360 * u(rng);
  std::vector<Joint> joints;
  for (int k = 0; k < m; ++k)
    joints.push_back(
        {40 + 30 * u(rng), std::fmod(turn + 360.0 * k / m + 20 * (u(rng) - 0.5) + 360, 360), apex});
  return joints;
}

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

bool says_snapped(const analysis::ReportBlock& b) {
  for (const auto& n : b.notes)
    if (n.find("taken through one corner") != std::string::npos) return true;
  return false;
}

TEST(SurveyPrecisionAnalysis, PointsMovedBelowItGiveTheExactPyramidsShape) {
  std::mt19937_64 rng(4043);
  std::srand(4043);  // Eigen's Random
  for (int draw = 0; draw < 60; ++draw) {
    std::vector<Joint> joints = random_joints(rng);
    const analysis::Report exact = analyse_json(pyramid_scene(joints, 1e-4));
    ASSERT_EQ(exact.blocks.size(), 2u);
    const double move = log_uniform(rng, 1e-8, 1e-6);
    for (auto& j : joints) j.point += move * Eigen::Vector3d::Random().normalized();
    SCOPED_TRACE("draw " + std::to_string(draw) + ", points moved by up to " +
                 std::to_string(move * 1e9) + " nm");
    analysis::Report r;
    ASSERT_NO_THROW(r = analyse_json(pyramid_scene(joints, 1e-4)));
    ASSERT_EQ(r.blocks.size(), 2u);
    const analysis::ReportBlock& w = r.blocks[0];
    ASSERT_EQ(w.id, "W");
    ASSERT_TRUE(w.volume.has_value());
    // The exact scene's W (every joint through the apex) has its corners;
    // the moved one has the same, the joints taken through one apex.
    EXPECT_EQ(w.vertices.size(), exact.blocks[0].vertices.size());
    EXPECT_TRUE(says_snapped(w));
    // Surface (< 200 m^2 for these blocks) x (the survey's move and the
    // snap's, a few times it: joints 40-70 degrees apart).
    EXPECT_NEAR(*w.volume, *exact.blocks[0].volume, 200 * 10 * move);
    EXPECT_EQ(r.blocks[1].id, "V");
    const nlohmann::json j = nlohmann::json::parse(storage::report_to_json(r));
    EXPECT_EQ(j.at("blocks").size(), 2u);
  }
}

TEST(SurveyPrecisionAnalysis, PointsMovedAboveItStillGiveEveryBlock) {
  std::mt19937_64 rng(4044);
  std::srand(4044);
  for (int draw = 0; draw < 60; ++draw) {
    std::vector<Joint> joints = random_joints(rng);
    const double move = log_uniform(rng, 1e-3, 1e-2);
    for (auto& j : joints) j.point += move * Eigen::Vector3d::Random().normalized();
    SCOPED_TRACE("draw " + std::to_string(draw) + ", points moved by up to " +
                 std::to_string(move * 1e3) + " mm");
    analysis::Report r;
    ASSERT_NO_THROW(r = analyse_json(pyramid_scene(joints, 1e-4)));
    ASSERT_EQ(r.blocks.size(), 2u);
    const analysis::ReportBlock& w = r.blocks[0];
    // Built (its joints kept where they are, or four of them that happen
    // to pass within the precision taken through one point), or reported
    // alone as marginal: never left out.
    EXPECT_TRUE(w.volume.has_value() || w.marginal);
    const nlohmann::json j = nlohmann::json::parse(storage::report_to_json(r));
    EXPECT_EQ(j.at("blocks").size(), 2u);
  }
}

TEST(SurveyPrecisionAnalysis, APrecisionOutsideAMicrometreToAMetreIsRefusedByName) {
  std::mt19937_64 rng(4045);
  const std::vector<Joint> joints = random_joints(rng);
  for (double precision : {0.0, 1e-7, 2.0, -1e-3}) {
    try {
      analyse_json(pyramid_scene(joints, precision));
      ADD_FAILURE() << precision << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("analysis.survey_precision_m"), std::string::npos)
          << e.what();
    }
  }
  for (double precision : {1e-6, 1e-3, 1.0}) {
    EXPECT_NO_THROW(analyse_json(pyramid_scene(joints, precision))) << precision;
  }
  // Not given: a micrometre, coordinates' rounding to six decimals.
  nlohmann::json scene = pyramid_scene(joints, 1e-4);
  scene["analysis"].erase("survey_precision_m");
  EXPECT_EQ(storage::parse_scene(scene.dump(), "W.scene.json").analysis.survey_precision_m, 1e-6);
}

}  // namespace
}  // namespace rockface
