// The whole analysis of a scene whose block W has four to six joints
// through one vertex, their points moved by 1e-11 to 1e-5 m as a survey
// gives them (issue 40): it used to stop with "block W: the half-spaces did
// not give a consistent polyhedron" and no report in 20-70 % of draws. Every
// draw must give a report with W built, its verdicts those of the unmoved
// scene (or marginal).
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/analysis/report.h"
#include "core/analysis/scene_analysis.h"
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

// W: below every joint (a pyramid with its apex up), above the free face
// z = 0 (a roof: the rock above it).
std::string pyramid_scene(const std::vector<Joint>& joints) {
  nlohmann::json s;
  s["format"] = "rockface-scene/1";
  s["rock"] = {{"density", 2650}};
  nlohmann::json halfspaces;
  for (size_t k = 0; k < joints.size(); ++k) {
    const std::string id = "J" + std::to_string(k + 1);
    const auto& p = joints[k].point;
    s["joints"].push_back({{"id", id},
                           {"dip", joints[k].dip},
                           {"dipdir", joints[k].dipdir},
                           {"point", {p.x(), p.y(), p.z()}},
                           {"friction", 30}});
    halfspaces[id] = "lower";
  }
  s["free_faces"].push_back(
      {{"id", "F1"}, {"dip", 0}, {"dipdir", 0}, {"point", {0, 0, 0}}, {"rock_side", "upper"}});
  halfspaces["F1"] = "upper";
  s["blocks"].push_back({{"id", "W"}, {"halfspaces", halfspaces}});
  s["analysis"] = {{"pyramids", false}, {"blocks", true}, {"rotation", true}};
  return s.dump(2);
}

analysis::Report analyse_text(const std::string& text) {
  const storage::Scene scene = storage::parse_scene(text, "W.scene.json");
  NoProgress progress;
  return analysis::analyse(app::analysis_input(scene), progress);
}

TEST(SharedVertexAnalysis, EveryDrawGivesAReportWithTheBlock) {
  std::mt19937_64 rng(4040);
  std::uniform_real_distribution<double> u(0, 1);
  for (int draw = 0; draw < 150; ++draw) {
    const Eigen::Vector3d apex(100 * u(rng), 100 * u(rng), 4 + u(rng));
    const int m = 4 + static_cast<int>(3 * u(rng));
    const double turn = 360 * u(rng);
    std::vector<Joint> joints;
    for (int k = 0; k < m; ++k)
      joints.push_back({40 + 30 * u(rng),
                        std::fmod(turn + 360.0 * k / m + 20 * (u(rng) - 0.5) + 360, 360), apex});
    const analysis::Report exact = analyse_text(pyramid_scene(joints));
    ASSERT_EQ(exact.blocks.size(), 1u);
    const double move = std::exp(std::log(1e-11) + u(rng) * (std::log(1e-5) - std::log(1e-11)));
    for (auto& j : joints) j.point += move * Eigen::Vector3d::Random().normalized();
    SCOPED_TRACE("draw " + std::to_string(draw) + ", points moved by up to " +
                 std::to_string(move * 1e9) + " nm");
    analysis::Report r;
    ASSERT_NO_THROW(r = analyse_text(pyramid_scene(joints)));
    ASSERT_EQ(r.blocks.size(), 1u);
    const analysis::ReportBlock& b = r.blocks[0];
    const analysis::ReportBlock& e = exact.blocks[0];
    EXPECT_EQ(b.id, "W");
    ASSERT_TRUE(b.volume.has_value());
    // Surface (< 200 m^2 for these blocks) x move, and the merge tolerance
    // of the construction (2e-9 x size < 1e-7 m on ~10 m): < 1e-4 m^3.
    EXPECT_NEAR(*b.volume, *e.volume, 200 * (move + 1e-7));
    EXPECT_EQ(b.finite, e.finite);
    if (!b.marginal && !e.marginal) {
      EXPECT_EQ(b.removable, e.removable);
    }
    ASSERT_EQ(b.mode.has_value(), e.mode.has_value());
    if (b.mode && !b.mode->marginal && !e.mode->marginal) {
      EXPECT_EQ(b.mode->type, e.mode->type);
      EXPECT_EQ(b.mode->planes, e.mode->planes);
    }
    // The report JSON is written whole.
    const nlohmann::json j = nlohmann::json::parse(storage::report_to_json(r));
    EXPECT_TRUE(j.at("blocks").at(0).contains("volume"));
  }
}

}  // namespace
}  // namespace rockface
