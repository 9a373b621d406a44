// `rockface measure` on free-face areas (picks `areas[].rock_side`) tapped
// either way round: the demo face replayed at the fast preset, its two
// walls outlined as free faces in the left photograph counter-clockwise and
// clockwise (as seen from the camera) in two visits, each visit's scene
// exported as the tablet's analysis exports it and analysed by the real
// binary. The rock lies behind the face the camera saw, whichever way the
// geologist went round it.
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "tests/support/cli_run.h"
#include "tests/support/demo_projects.h"
#include "tests/support/json_file.h"
#include "tests/support/test_paths.h"
#include "tests/support/truth_picks.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::CliRun;
using rockface::test::read_json;
using rockface::test::run_rockface;
using rockface::test::write_json;

// The sample's own taps of its traces, each with the compass reading a
// geologist takes on its joint (the sample's J2 reading; J1 and J3 read to
// the degree as the scene gives them), without the joint names: a visit of
// `rockface measure` stores one joint per known plane, named after its
// trace, and no joint fitted to several traces by name. S1 (T2 traced
// again) is left out: it is the same discontinuity.
json sample_traces() {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json");
  const std::map<std::string, json> reading{{"J1", {{"dip", 60.0}, {"dip_direction", 200.0}}},
                                            {"J2", {{"dip", 74.0}, {"dip_direction", 111.0}}},
                                            {"J3", {{"dip", 20.0}, {"dip_direction", 350.0}}}};
  const json sample = json::parse(in);
  json traces = json::array();
  for (json t : sample.at("picks").at("traces")) {
    if (!t.contains("pixels")) continue;
    t["compass"] = reading.at(t.at("joint").get<std::string>());
    t.erase("joint");
    traces.push_back(t);
  }
  return traces;
}

// The two walls of the demo face in the left photograph (1500 x 1000 px),
// 80 px in from the sides and 40 px from the top and bottom, where dense
// matching leaves surface (tests/support/truth_picks.h): the fold between
// them, x = 512340 m, projects to u = 745.9 at v = 40 and u = 749.3 at
// v = 960 (the demo's left camera), so the two outlines share those two
// corners and their patches share that edge in 3D. Listed counter-
// clockwise as the camera sees them (image v grows downwards).
const std::vector<std::vector<std::array<double, 2>>> kWallsCounterClockwise{
    {{150, 60}, {150, 940}, {749.2, 940}, {746.0, 60}},     // FACE_W
    {{746.0, 60}, {749.2, 940}, {1350, 940}, {1350, 60}}};  // FACE_E

json free_faces(bool clockwise) {
  json areas = json::array();
  for (std::size_t k = 0; k < kWallsCounterClockwise.size(); ++k) {
    auto corners = kWallsCounterClockwise[k];
    if (clockwise) std::reverse(corners.begin(), corners.end());
    json polygon = json::array();
    for (const auto& c : corners) polygon.push_back({c[0], c[1]});
    areas.push_back({{"id", k == 0 ? "FW" : "FE"},
                     {"photo", "left"},
                     {"polygon", polygon},
                     {"rock_side", "lower"}});  // the walls lean back: the rock is below them
  }
  return areas;
}

struct Visit {
  rockface::storage::RecordId id = 0;
  std::string said;  // what the verb printed
  json measures;     // MEASURES.json
  json scene;        // as the tablet's analysis exports the visit
  json report;       // `rockface analyse` of that scene
};

Visit measure_and_analyse(const fs::path& dir, const fs::path& project, bool clockwise) {
  const std::string name = clockwise ? "cw" : "ccw";
  const json picks = {{"format", "rockface-picks/1"},
                      {"traces", sample_traces()},
                      {"areas", free_faces(clockwise)}};
  write_json(dir / (name + ".picks.json"), picks);
  Visit v;
  const fs::path out = dir / (name + ".measures.json");
  const CliRun r = run_rockface("measure " + project.string() + " --traces " +
                                (dir / (name + ".picks.json")).string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return v;
  v.said = r.out;
  v.measures = read_json(out);
  {
    auto store = rockface::storage::ProjectStore::open(project);
    v.id = *store.latest_visit();
    v.scene = rockface::storage::make_scene_json(rockface::storage::load_scene_source(store, v.id));
  }
  write_json(dir / (name + ".scene.json"), v.scene);
  const CliRun a = run_rockface("analyse " + (dir / (name + ".scene.json")).string() + " --out " +
                                (dir / (name + ".report.json")).string());
  EXPECT_EQ(a.exit_code, 0) << a.err;
  if (a.exit_code == 0) v.report = read_json(dir / (name + ".report.json"));
  return v;
}

// The same cyclic sequence read from some start (a stored polygon may start
// at any corner; its turning sense is what carries the rock side).
template <typename T>
bool same_cycle(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t shift = 0; shift < a.size(); ++shift) {
    bool same = true;
    for (std::size_t i = 0; i < a.size() && same; ++i) same = a[i] == b[(i + shift) % b.size()];
    if (same) return true;
  }
  return a.empty();
}

std::map<std::string, rockface::storage::Measurement> stored_areas(
    const fs::path& project, rockface::storage::RecordId visit) {
  std::map<std::string, rockface::storage::Measurement> out;
  auto store = rockface::storage::ProjectStore::open(project);
  for (auto& m : store.list_measurements(visit))
    if (m.kind == rockface::storage::Measurement::Kind::area) out[m.label] = m;
  return out;
}

TEST(FreeFaceWinding, EitherTapOrderGivesTheSameRecordAndTheSameBlocks) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-free-face-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path project = dir / "site.rockface";
  // The demo face without its picks at the fast preset (the fixture's
  // "bare" replay under CTest).
  ASSERT_NO_THROW(rockface::test::copy_of_shared_demo_project("bare", project));

  const Visit ccw = measure_and_analyse(dir, project, false);
  const Visit cw = measure_and_analyse(dir, project, true);
  ASSERT_FALSE(ccw.report.is_null());
  ASSERT_FALSE(cw.report.is_null());
  ASSERT_NE(ccw.id, cw.id);

  // MEASURES.json: each wall a free face, its rock behind it as the left
  // camera sees it ("lower": the walls lean back 2-3 deg, dip ~87.7 deg
  // toward the camera), told by the photograph, seen at ~65-70 deg; the
  // same plane and corners either way round (the same mesh vertices inside
  // the same polygon: the same numbers).
  for (const char* id : {"FW", "FE"}) {
    std::map<std::string, json> x;
    for (const Visit* v : {&ccw, &cw})
      for (const auto& m : v->measures.at("measurements"))
        if (m.at("id") == id) x[v == &ccw ? "ccw" : "cw"] = m;
    ASSERT_EQ(x.size(), 2u) << id;
    for (const auto& [order, m] : x) {
      ASSERT_TRUE(m.at("orientation_known").get<bool>()) << id << " " << order;
      EXPECT_EQ(m.at("rock_side"), "lower") << id << " " << order;
      EXPECT_EQ(m.at("rock_side_from"), "photograph") << id << " " << order;
      EXPECT_FALSE(m.at("marginal").get<bool>()) << id << " " << order;
      EXPECT_GT(m.at("seen_at_deg").get<double>(), m.at("seen_needs_deg").get<double>());
      EXPECT_EQ(m.at("note"), "") << id << " " << order;
    }
    for (const char* field : {"dip", "dipdir", "sigma_deg", "centroid", "area_m2", "pixels"})
      EXPECT_EQ(x["ccw"].at(field), x["cw"].at(field)) << id << " " << field;
  }

  // The verb says it, per free face.
  for (const Visit* v : {&ccw, &cw})
    for (const char* id : {"FW: free face ", "FE: free face "}) {
      const auto at = v->said.find(id);
      ASSERT_NE(at, std::string::npos) << v->said;
      EXPECT_NE(v->said.find("rock lower (behind the face photographed, seen at ", at),
                std::string::npos)
          << v->said;
    }

  // The stored records: the same plane, rock side and corners, in the same
  // turning sense (counter-clockwise seen from the camera: out of the rock).
  const auto a = stored_areas(project, ccw.id), b = stored_areas(project, cw.id);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  for (const auto& [label, m] : a) {
    const auto& n = b.at(label);
    EXPECT_EQ(m.rock_side, "lower");
    EXPECT_EQ(n.rock_side, m.rock_side) << label;
    EXPECT_EQ(n.dip_deg, m.dip_deg) << label;
    EXPECT_EQ(n.dipdir_deg, m.dipdir_deg) << label;
    EXPECT_TRUE(same_cycle(m.points, n.points)) << label;
    EXPECT_TRUE(same_cycle(m.pixels, n.pixels)) << label;
  }

  // The scene the tablet's analysis exports from each visit: the same free
  // faces and surface patches (the analysis takes a patch's rock side from
  // its corners' turning sense, SCENE.md).
  EXPECT_EQ(ccw.scene.at("free_faces"), cw.scene.at("free_faces"));
  EXPECT_EQ(ccw.scene.at("surface"), cw.scene.at("surface"));

  // The analysis: the demo's keyblock (J1 x J2 x J3 on the face: the
  // traces T1-T5) finite and removable, sliding, and the very same report
  // either way round (same scene in, same numbers out).
  const json& blocks = ccw.report.at("blocks");
  ASSERT_EQ(blocks.size(), 1u) << blocks.dump(1);
  EXPECT_TRUE(blocks[0].at("finite").get<bool>()) << blocks[0].dump(1);
  EXPECT_TRUE(blocks[0].at("removable").get<bool>()) << blocks[0].dump(1);
  EXPECT_GT(blocks[0].at("volume").get<double>(), 0.5);  // the replay's TB1: 0.72 m^3
  EXPECT_LT(blocks[0].at("volume").get<double>(), 1.0);
  EXPECT_EQ(blocks[0].at("mode").at("type"), "sliding");
  EXPECT_EQ(ccw.report.at("blocks"), cw.report.at("blocks"));
  EXPECT_EQ(ccw.report.at("pyramids"), cw.report.at("pyramids"));
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
