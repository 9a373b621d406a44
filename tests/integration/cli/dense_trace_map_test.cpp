// A densely mapped face (issue 28): a trace map with a joint plane per trace
// analyses on the command line, the blocks from every trace and the joint
// pyramid table over the joints' sets (2^n codes of 30 or 200 joints would
// not fit in memory); more joints than a table can take in a scene without
// traces are refused as bad input saying what to do.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/dense_face.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::CliRun;
using rockface::test::run_rockface;

nlohmann::json xyz(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

// The face as a scene: each trace's own joint, the face as a free face
// (rock to the north, below its upward normal) and as the surface patch.
nlohmann::json dense_scene(const rockface::test::DenseFace& face) {
  nlohmann::json joints = nlohmann::json::array(), traces = nlohmann::json::array();
  for (const auto& t : face.traces) {
    joints.push_back({{"id", t.joint},
                      {"dip", t.dip},
                      {"dipdir", t.dipdir},
                      {"point", xyz(t.point)},
                      {"friction", t.friction},
                      {"cohesion", 0}});
    traces.push_back({{"id", t.id}, {"joint", t.joint}, {"points", {xyz(t.from), xyz(t.to)}}});
  }
  nlohmann::json polygon = nlohmann::json::array();
  for (const auto& p : face.polygon()) polygon.push_back(xyz(p));
  return {{"format", "rockface-scene/1"},
          {"name", "densely mapped face"},
          {"rock", {{"density", 2700}}},
          {"joints", joints},
          {"free_faces",
           {{{"id", "F1"},
             {"dip", 90},
             {"dipdir", 180},
             {"point", {0, 0, 0}},
             {"rock_side", "lower"}}}},
          {"surface", {{"patches", {{{"id", "FACE"}, {"polygon", polygon}}}}}},
          {"traces", traces},
          {"analysis", {{"preset", "fast"}, {"rotation", false}}}};
}

struct Analysed {
  CliRun run;
  nlohmann::json report;
};

Analysed analyse(const nlohmann::json& scene, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "scene.json") << scene.dump();
  Analysed a;
  a.run = run_rockface("analyse " + (dir / "scene.json").string() + " --out " +
                       (dir / "report.json").string());
  if (a.run.exit_code == 0) a.report = nlohmann::json::parse(std::ifstream(dir / "report.json"));
  fs::remove_all(dir);
  return a;
}

// Blocks from the traces, each with its verdicts and margin; the pyramid
// table over the three sets (a code digit per set), its note naming them.
void expect_blocks_and_set_table(const nlohmann::json& report, size_t joints) {
  int trace_blocks = 0, finite = 0, with_mode = 0;
  for (const auto& b : report.at("blocks")) {
    if (b.at("source") != "traces") continue;
    ++trace_blocks;
    EXPECT_TRUE(b.at("finite").is_boolean());
    EXPECT_TRUE(b.at("removable").is_boolean());
    EXPECT_TRUE(b.at("margin_deg").is_number());
    if (b.at("finite").get<bool>()) ++finite;
    if (b.contains("mode")) ++with_mode;
  }
  EXPECT_GT(trace_blocks, 0);
  EXPECT_GT(finite, 0);
  EXPECT_GT(with_mode, 0);
  const auto& pyramids = report.at("pyramids");
  ASSERT_EQ(pyramids.size(), 8u) << "2^3 codes of three sets against one face";
  for (const auto& p : pyramids) EXPECT_EQ(p.at("code").get<std::string>().size(), 3u);
  bool over_sets = false;
  for (const auto& n : report.at("notes")) {
    const std::string note = n.get<std::string>();
    if (note.find("pyramids: " + std::to_string(joints) + " joints") == std::string::npos) continue;
    over_sets = note.find("over their 3 joint sets") != std::string::npos &&
                note.find("S1 ") != std::string::npos;
  }
  EXPECT_TRUE(over_sets) << report.at("notes").dump();
}

TEST(DenseTraceMap, ThirtyPlanesAnalyse) {
  const Analysed a = analyse(dense_scene(rockface::test::dense_face(30)), "dense-30");
  ASSERT_EQ(a.run.exit_code, 0) << a.run.err;
  expect_blocks_and_set_table(a.report, 30);
}

TEST(DenseTraceMap, TwoHundredTracesWithTwoHundredPlanesAnalyse) {
  const Analysed a = analyse(dense_scene(rockface::test::dense_face(200)), "dense-200");
  ASSERT_EQ(a.run.exit_code, 0) << a.run.err;
  expect_blocks_and_set_table(a.report, 200);
  int trace_blocks = 0;
  for (const auto& b : a.report.at("blocks")) trace_blocks += b.at("source") == "traces";
  // 200 traces of 2-8 m on a 20 x 10 m face cut it into hundreds of loops.
  EXPECT_GT(trace_blocks, 100);
}

}  // namespace
