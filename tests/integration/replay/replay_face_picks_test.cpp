// `rockface replay` of a visit photographed as three stereo pairs, with picks
// in more than one pair's photograph: every pick is measured on its own
// pair's 3D image, registered into the face frame; a joint trace picked
// partly in pair 1's left photograph and partly in pair 2's becomes one
// trace; the block analysis runs on the joined traces.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/project/project_store.h"
#include "storage/scene/picks_json.h"
#include "tests/support/cli_run.h"
#include "tests/support/plane_angle.h"
#include "tests/support/truth_picks.h"

namespace {

namespace fs = std::filesystem;

using rockface::test::CliRun;
using rockface::test::plane_angle_deg;
using rockface::test::pole_of;
using rockface::test::run_rockface;
using rockface::test::TruthTrace;

// The picks' demo scene (truth_picks.h) with a second and third pair, the
// stations moved 1.2 m west (pair 2) and east (pair 3).
nlohmann::json three_pair_scene() {
  nlohmann::json scene = rockface::test::demo_scene();
  const nlohmann::json first = scene["imaging"]["stations"];
  for (double dx : {-1.2, 1.2})
    for (auto st : first) {
      st["position"][0] = st["position"][0].get<double>() + dx;
      st["look_at"][0] = st["look_at"][0].get<double>() + dx;
      scene["imaging"]["stations"].push_back(st);
    }
  return scene;
}

// Only the stations of pair `k` (0-based): rendered, its truth.json gives the
// true traces' pixels in that pair's left photograph.
nlohmann::json pair_only(const nlohmann::json& scene, int k) {
  nlohmann::json one = scene;
  one["imaging"]["stations"] = {scene["imaging"]["stations"][2 * k],
                                scene["imaging"]["stations"][2 * k + 1]};
  return one;
}

// The part of a true trace between fractions [from, to] of its pixels.
TruthTrace part(const TruthTrace& t, double from, double to) {
  TruthTrace p = t;
  const auto n = static_cast<double>(t.pixels.size() - 1);
  p.pixels.assign(t.pixels.begin() + static_cast<long>(from * n),
                  t.pixels.begin() + static_cast<long>(to * n) + 1);
  return p;
}

class ReplayFacePicks : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rockface-replay-face-picks-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<TruthTrace> rendered_traces(const nlohmann::json& scene, const std::string& name) {
    std::ofstream(dir_ / (name + ".scene.json")) << scene.dump(2);
    const CliRun r = run_rockface("render " + (dir_ / (name + ".scene.json")).string() + " --out " +
                                  (dir_ / name).string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return rockface::test::face_traces(dir_ / name / "truth.json");
  }

  fs::path dir_;
};

}  // namespace

TEST_F(ReplayFacePicks, ATracePickedInTwoPairsIsOneTraceAndTheBlocksComeFromIt) {
  nlohmann::json scene = three_pair_scene();
  const auto first = rendered_traces(pair_only(scene, 0), "pair1");
  const auto second = rendered_traces(pair_only(scene, 1), "pair2");
  // J1 on the west facet runs from the fold (x = 512340) down to the floor
  // (x = 512337.8); both photographs see it (the range pole, 2 m in front
  // of the face, hides parts of the east facet's traces, not of this one).
  // Pair 1 gets the 60 % next to the fold, pair 2 (1.2 m west) the western
  // 60 % (the pixels run from the fold westwards): they overlap on 20 %.
  auto j1_west = [](const std::vector<TruthTrace>& ts) {
    for (const auto& t : ts)
      if (t.joint == "J1" && t.patch == "FACE_W") return t;
    ADD_FAILURE() << "no J1 trace on FACE_W";
    return TruthTrace{};
  };
  const TruthTrace in_first = j1_west(first), in_second = j1_west(second);
  ASSERT_GE(in_first.pixels.size(), 100u);
  ASSERT_GE(in_second.pixels.size(), 100u);

  nlohmann::json picks = nlohmann::json::array();
  std::string joined_first;
  for (const auto& t : first) {
    const std::string id = "T" + std::to_string(picks.size() + 1);
    const bool split = t.joint == "J1" && t.patch == "FACE_W";
    if (split) joined_first = id;
    picks.push_back({{"id", id},
                     {"joint", t.joint},
                     {"photo", "left"},
                     {"pixels", rockface::test::taps_along(split ? part(t, 0.0, 0.6) : t, 8)}});
  }
  ASSERT_FALSE(joined_first.empty());
  picks.push_back({{"id", "P2"},
                   {"joint", "J1"},
                   {"pair", 2},
                   {"photo", "left"},
                   {"pixels", rockface::test::taps_along(part(in_second, 0.4, 1.0), 8)}});
  // An area and a point in pair 2's left photograph, on FACE_W (west of the
  // fold, which pair 2, 1.2 m west, sees at u ~ 1030; away from the range
  // pole): measured on pair 2's 3D image in the face frame.
  const nlohmann::json area2 = {{"id", "A2"},
                                {"pair", 2},
                                {"photo", "left"},
                                {"polygon", {{400, 600}, {600, 600}, {600, 800}, {400, 800}}}};
  const nlohmann::json point2 = {
      {"id", "Q2"}, {"pair", 2}, {"photo", "left"}, {"pixel", {500, 700}}, {"radius", 0.3}};
  scene["picks"] = {{"traces", picks}, {"areas", {area2}}, {"points", {point2}}};
  const fs::path file = dir_ / "three-pairs.scene.json";
  std::ofstream(file) << scene.dump(2);
  const fs::path project = dir_ / "site.rockface";
  // The scene's preset (standard): at the fast preset the 3D image has holes
  // under taps of the east facet's traces next to the range pole, which the
  // replay refuses (no surface under the pick).
  const CliRun r = run_rockface("replay " + file.string() + " --project " + project.string());
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  std::printf("%s\n", r.out.c_str());

  auto store = rockface::storage::ProjectStore::open(project);
  const auto visit = store.latest_visit();
  ASSERT_TRUE(visit);
  ASSERT_EQ(store.list_captures(*visit).size(), 3u);
  // One trace record per picked trace, the two pieces of J1 as one.
  std::map<std::string, rockface::storage::Measurement> traces;
  for (const auto& m : store.list_measurements(*visit))
    if (m.kind == rockface::storage::Measurement::Kind::trace) traces[m.label] = m;
  EXPECT_EQ(traces.size(), picks.size() - 1);
  EXPECT_EQ(traces.count("P2"), 0u) << "P2 is stored on its own, not joined";
  ASSERT_EQ(traces.count(joined_first), 1u);
  const auto& joined = traces.at(joined_first);
  EXPECT_NE(joined.note.find("joined from"), std::string::npos) << joined.note;
  EXPECT_NE(joined.note.find("P2"), std::string::npos) << joined.note;
  // Its points span both pieces: the trace runs 2.2 m in x (less where
  // the photographs' bottom rows are left out, truth_picks.h); each piece
  // alone covers 60 % of what its photograph shows, at most 1.34 m.
  double x_min = 1e9, x_max = -1e9;
  for (const auto& p : joined.points) {
    x_min = std::min(x_min, p.x());
    x_max = std::max(x_max, p.x());
  }
  ASSERT_TRUE(joined.trace_length_m);
  std::printf("joined trace: %zu points, x %.3f..%.3f, length %.3f m\n", joined.points.size(),
              x_min, x_max, *joined.trace_length_m);
  EXPECT_GT(x_max - x_min, 1.5);

  // The joined trace lies on the flat west facet: straight, it has no
  // plane of its own (its record says why).
  EXPECT_FALSE(joined.dip_deg) << joined.note;
  // The joint J1's plane, fitted over all its traces (both pieces and the
  // east facet's trace, which gives the relief across the fold), in the
  // face frame. Expected error as in replay_picks_test.cpp: the fit's sigma
  // (0.2-0.5 deg) plus the registration's vertical and north (~0.1 deg);
  // pair 2's samples add its registration to pair 1 (surface rms ~1 cm,
  // tie points over metres: < 0.1 deg). Seen: 0.29 deg.
  const Eigen::Vector3d j1 = pole_of(60, 200);
  bool found = false;
  for (const auto& j : store.list_joints(*visit)) {
    if (j.label != "J1") continue;
    found = true;
    EXPECT_NE(j.source.find("P2"), std::string::npos) << j.source;
    const double e = plane_angle_deg(pole_of(j.dip_deg, j.dipdir_deg), j1);
    std::printf("J1 measured %.2f/%.2f, error %.2f deg\n", j.dip_deg, j.dipdir_deg, e);
    EXPECT_LT(e, 1.0);
  }
  EXPECT_TRUE(found);

  // The blocks come from those traces: every block's traces are picked
  // ones, never P2 on its own (it is part of the joined trace).
  const auto runs = store.list_analyses(*visit);
  ASSERT_EQ(runs.size(), 1u);
  int finite = 0;
  bool uses_joined = false;
  for (const auto& b : store.load_analysis(runs[0].id).blocks) {
    EXPECT_EQ(b.source, "traces");
    const auto j = nlohmann::json::parse(b.report_json);
    for (const auto& t : j.at("traces")) {
      const std::string id = t.get<std::string>();
      EXPECT_TRUE(traces.count(id)) << id;
      if (id == joined_first) uses_joined = true;
    }
    if (j.value("finite", false)) ++finite;
  }
  EXPECT_GE(finite, 1);
  EXPECT_TRUE(uses_joined);

  // The area and the point of pair 2: on pair 2's 3D image, stored with
  // pair 2's model and capture, in the face frame. FACE_W: y = 5211880 +
  // 0.1 (x - 512337) + 0.04 (z - 410) (truth_picks.h). Expected error as
  // for an area of pair 1 (measure_cli_test.cpp: the fit's own error is
  // hundredths of a degree, the registration's ~0.1 deg and dense
  // matching's smoothing dominate, < 0.5 deg), plus pair 2's registration
  // onto pair 1 (< 0.1 deg, above); a point's local plane (0.3 m radius) as
  // there, < 2 deg.
  const auto captures = store.list_captures(*visit);
  const auto pairs = store.list_visit_models(*visit);
  ASSERT_EQ(pairs.size(), 3u);
  const Eigen::Vector3d face_w(-0.1, 1.0, -0.04);
  std::map<std::string, rockface::storage::Measurement> by_label;
  for (const auto& m : store.list_measurements(*visit)) by_label[m.label] = m;
  for (const auto& [id, bound] : std::map<std::string, double>{{"A2", 0.6}, {"Q2", 2.0}}) {
    ASSERT_EQ(by_label.count(id), 1u) << id;
    const auto& m = by_label.at(id);
    EXPECT_EQ(m.photo, "pair 2 left") << id;
    EXPECT_EQ(m.model_id, pairs[1].id) << id;
    EXPECT_EQ(m.photo_capture_id, captures[1].id) << id;
    ASSERT_TRUE(m.dip_deg) << id << ": " << m.note;
    const double e = plane_angle_deg(pole_of(*m.dip_deg, *m.dipdir_deg), face_w.normalized());
    std::printf("%s (pair 2) measured %.2f/%.2f, error %.2f deg\n", id.c_str(), *m.dip_deg,
                *m.dipdir_deg, e);
    EXPECT_LT(e, bound) << id;
  }
  // A trace of pair 1 keeps pair 1's model and capture.
  EXPECT_EQ(by_label.at(joined_first).model_id, pairs[0].id);
  EXPECT_EQ(by_label.at(joined_first).photo_capture_id, captures[0].id);

  // `rockface measure` on the project: the same picks of pair 2 on the
  // visit's pair 2 (the newest visit with a model), in the face frame.
  const nlohmann::json pick_file = {
      {"format", "rockface-picks/1"},
      {"traces",
       {{{"id", "P2"},
         {"pair", 2},
         {"photo", "left"},
         {"pixels", rockface::test::taps_along(part(in_second, 0.4, 1.0), 8)}}}},
      {"areas", {area2}},
      {"points", {point2}}};
  std::ofstream(dir_ / "picks.json") << pick_file.dump(2);
  const std::size_t visits_before = store.list_visits().size();
  const CliRun m =
      run_rockface("measure " + project.string() + " --traces " + (dir_ / "picks.json").string() +
                   " --out " + (dir_ / "measures.json").string());
  ASSERT_EQ(m.exit_code, 0) << m.err << m.out;
  const auto measured_visit = store.latest_visit();
  ASSERT_NE(measured_visit, visit);
  std::map<std::string, rockface::storage::Measurement> measured;
  for (const auto& x : store.list_measurements(*measured_visit)) measured[x.label] = x;
  ASSERT_EQ(measured.size(), 3u);
  for (const auto& [id, x] : measured) {
    EXPECT_EQ(x.photo, "pair 2 left") << id;
    EXPECT_EQ(x.model_id, pairs[1].id) << id;
    EXPECT_EQ(x.photo_capture_id, captures[1].id) << id;
  }
  // The same 3D image and the same view as the replay's (the stored mesh in
  // double precision, the camera's map through a quaternion): the same
  // plane, up to the outlier test's threshold, which the verb takes from
  // the stored report's precision rather than the reconstruction's.
  for (const std::string id : {"A2", "Q2"}) {
    ASSERT_TRUE(measured.at(id).dip_deg) << id << ": " << measured.at(id).note;
    const double d =
        plane_angle_deg(pole_of(*measured.at(id).dip_deg, *measured.at(id).dipdir_deg),
                        pole_of(*by_label.at(id).dip_deg, *by_label.at(id).dipdir_deg));
    std::printf("%s: rockface measure vs replay %.4f deg\n", id.c_str(), d);
    EXPECT_LT(d, 0.05) << id;
  }
  // P2 alone lies on the flat west facet: a straight line, no plane. Its
  // points are in the face frame where the true J1 trace is: on J1's plane
  // and on FACE_W's. A view of pair 2 built from anything but its camera's
  // map onto the face would put them elsewhere or miss the surface.
  EXPECT_FALSE(measured.at("P2").dip_deg);
  ASSERT_FALSE(measured.at("P2").points.empty());
  const Eigen::Vector3d datum = store.project().datum;
  Eigen::Vector3d j1_point = Eigen::Vector3d::Zero();
  for (const auto& j : scene["joints"])
    if (j["id"] == "J1")
      j1_point = {j["point"][0].get<double>(), j["point"][1].get<double>(),
                  j["point"][2].get<double>()};
  const Eigen::Vector3d face_w_point(512337, 5211880, 410);
  double off_j1 = 0, off_face = 0;
  for (const auto& p : measured.at("P2").points) {
    off_j1 = std::max(off_j1, std::abs((p + datum - j1_point).dot(j1)));
    off_face = std::max(off_face, std::abs((p + datum - face_w_point).dot(face_w.normalized())));
  }
  std::printf("P2: farthest of its points from J1's plane %.4f m, from FACE_W's %.4f m\n", off_j1,
              off_face);
  // The taps are the true trace's pixels (sub-pixel, ~4 mm at 10 m), the
  // surface under them is dense matching's (sigma_Z ~7 mm, smoothed across
  // the dark trace), and the face frame is the registration's (~0.1 deg,
  // ~1.5 cm at 10 m from the pole): a few centimetres.
  EXPECT_LT(off_j1, 0.05);
  EXPECT_LT(off_face, 0.05);

  // `rockface measure` with J1's piece of pair 1 (as the replay's) and P2:
  // as in the replay, one trace (named in the output and stdout), stored
  // as one record; each measurement names its own pair's model.
  const nlohmann::json both_file = {
      {"format", "rockface-picks/1"},
      {"traces",
       {{{"id", "W1"},
         {"joint", "J1"},
         {"photo", "left"},
         {"pixels", rockface::test::taps_along(part(in_first, 0.0, 0.6), 8)}},
        {{"id", "P2"},
         {"joint", "J1"},
         {"pair", 2},
         {"photo", "left"},
         {"pixels", rockface::test::taps_along(part(in_second, 0.4, 1.0), 8)}}}}};
  std::ofstream(dir_ / "both.json") << both_file.dump(2);
  const CliRun w =
      run_rockface("measure " + project.string() + " --traces " + (dir_ / "both.json").string() +
                   " --out " + (dir_ / "both-measures.json").string());
  ASSERT_EQ(w.exit_code, 0) << w.err << w.out;
  EXPECT_NE(w.out.find("W1: one trace across the pairs' photographs (W1, P2)"), std::string::npos)
      << w.out;
  nlohmann::json out;
  std::ifstream(dir_ / "both-measures.json") >> out;
  const std::string model_name = project.string() + " model ";
  EXPECT_EQ(out["model"], model_name + std::to_string(pairs[0].id));
  ASSERT_EQ(out["measurements"].size(), 2u);
  for (const auto& x : out["measurements"]) {
    const bool second_pair = x["id"] == "P2";
    EXPECT_EQ(x["pair"], second_pair ? 2 : 1) << x["id"];
    EXPECT_EQ(x["model"], model_name + std::to_string(pairs[second_pair ? 1 : 0].id)) << x["id"];
    EXPECT_EQ(x["joined_into"], "W1") << x["id"];
  }
  ASSERT_EQ(out["joined_traces"].size(), 1u);
  const auto& jw = out["joined_traces"][0];
  EXPECT_EQ(jw["id"], "W1");
  EXPECT_EQ(jw["joint"], "J1");
  EXPECT_EQ(jw["pieces"], nlohmann::json::array({"W1", "P2"}));
  EXPECT_EQ(jw["pairs"], nlohmann::json::array({1, 2}));
  const auto both_visit = store.latest_visit();
  ASSERT_NE(both_visit, measured_visit);
  std::vector<rockface::storage::Measurement> both;
  for (const auto& x : store.list_measurements(*both_visit))
    if (x.kind == rockface::storage::Measurement::Kind::trace) both.push_back(x);
  ASSERT_EQ(both.size(), 1u) << "P2 is in W1";
  EXPECT_EQ(both[0].label, "W1");
  EXPECT_NE(both[0].note.find("joined from W1 P2"), std::string::npos) << both[0].note;
  EXPECT_EQ(both[0].model_id, pairs[0].id);
  // It spans both pieces as the replay's joined trace does: the same taps
  // on the same 3D images; the replay's points are the taps' nearest
  // vertices, measure's the samples between the taps (their ends the same
  // taps), so the ends agree to a mesh cell or two (~1 cm each; seen 2 mm).
  double wx_min = 1e9, wx_max = -1e9;
  for (const auto& p : both[0].points) {
    wx_min = std::min(wx_min, p.x());
    wx_max = std::max(wx_max, p.x());
  }
  std::printf("measure's joined trace: %zu points, x %.3f..%.3f (replay's %.3f..%.3f)\n",
              both[0].points.size(), wx_min, wx_max, x_min, x_max);
  EXPECT_GT(wx_max - wx_min, 1.5);
  EXPECT_NEAR(wx_min, x_min, 0.02);
  EXPECT_NEAR(wx_max, x_max, 0.02);
  // Its length as the replay's: the same ends, a straight trace on the
  // flat west facet (taps or samples along it alike); the ends' 2 mm, and
  // the samples' wander across the run (dense matching, ~1 cm) counted
  // over 5 cm steps: < 2 cm.
  ASSERT_TRUE(both[0].trace_length_m);
  std::printf("measure's joined trace length %.3f m (replay's %.3f m)\n", *both[0].trace_length_m,
              *joined.trace_length_m);
  EXPECT_NEAR(*both[0].trace_length_m, *joined.trace_length_m, 0.02);
  // Censored as the joined trace's own ends are (W1's end where P2 takes
  // over is inside the trace), in the output and in the stored record.
  ASSERT_TRUE(jw["censored"].is_boolean());
  EXPECT_EQ(both[0].censored, jw["censored"].get<bool>());

  // A pick naming a pair the visit lacks, or a further pair with --model
  // (one 3D image): bad input naming the field, nothing stored.
  nlohmann::json bad = pick_file;
  bad["areas"][0]["pair"] = 4;
  std::ofstream(dir_ / "bad.json") << bad.dump(2);
  CliRun b =
      run_rockface("measure " + project.string() + " --traces " + (dir_ / "bad.json").string() +
                   " --out " + (dir_ / "bad-out.json").string());
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("bad.json: areas[0].pair: pair 4, but visit"), std::string::npos) << b.err;
  EXPECT_NE(b.err.find("has 3 pairs"), std::string::npos) << b.err;
  b = run_rockface("measure " + project.string() + " --model " + std::to_string(pairs[0].id) +
                   " --traces " + (dir_ / "picks.json").string() + " --out " +
                   (dir_ / "bad-out.json").string());
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("picks.json: traces[0].pair: pair 2, but model"), std::string::npos)
      << b.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad-out.json"));
  EXPECT_EQ(store.list_visits().size(), visits_before + 2);
}

TEST_F(ReplayFacePicks, APickNamingAPairTheSceneDoesNotHaveIsBadInput) {
  nlohmann::json scene = three_pair_scene();
  scene["picks"] = {{"traces",
                     {{{"id", "T1"},
                       {"joint", "J1"},
                       {"pair", 4},
                       {"photo", "left"},
                       {"pixels", {{700, 500}, {760, 540}}}}}}};
  const fs::path file = dir_ / "bad.scene.json";
  std::ofstream(file) << scene.dump(2);
  const fs::path project = dir_ / "site.rockface";
  const CliRun r =
      run_rockface("replay " + file.string() + " --project " + project.string() + " --preset fast");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("picks.traces[0].pair"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("3 pairs"), std::string::npos) << r.err;
  // Refused before anything is captured: nothing stored.
  EXPECT_FALSE(fs::exists(project));

  // An area or a point naming it likewise.
  scene["picks"] = {
      {"areas",
       {{{"id", "A1"}, {"pair", 2}, {"photo", "left"}, {"polygon", {{1, 2}, {3, 4}, {5, 1}}}}}},
      {"points", {{{"id", "Q1"}, {"pair", 5}, {"photo", "left"}, {"pixel", {1, 2}}}}}};
  std::ofstream(file) << scene.dump(2);
  const CliRun p =
      run_rockface("replay " + file.string() + " --project " + project.string() + " --preset fast");
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("picks.points[0].pair: pair 5, but imaging.stations gives 3 pairs"),
            std::string::npos)
      << p.err;
  EXPECT_FALSE(fs::exists(project));
}

// A pick outside its photograph (a tap, an end of a semi-automatic trace,
// an area's corner, a point) is refused like a bad pair: exit 2 naming the
// pick, before anything is captured; an existing project file is left as it
// was, byte for byte, and none is created.
TEST_F(ReplayFacePicks, APickOutsideItsPhotographIsRefusedBeforeAnythingIsCaptured) {
  const nlohmann::json scene = three_pair_scene();
  const int width = scene["imaging"]["camera"]["width"].get<int>();
  const int height = scene["imaging"]["camera"]["height"].get<int>();
  const fs::path file = dir_ / "bad-pick.scene.json";
  const fs::path fresh = dir_ / "fresh.rockface", existing = dir_ / "existing.rockface";
  {
    rockface::storage::ProjectInfo info;
    info.name = "existing";
    rockface::storage::ProjectStore::create(existing, info).begin_visit("tablet");
  }
  const auto bytes = [](const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string before = bytes(existing);
  struct Bad {
    nlohmann::json picks;
    std::string where, what;
  };
  const std::vector<Bad> bad = {
      {{{"traces",
         {{{"id", "T1"},
           {"joint", "J1"},
           {"photo", "left"},
           {"pixels", {{700, 500}, {width + 40, 540}}}}}}},
       "picks.traces[0].pixels[1]",
       "is outside the left photograph"},
      {{{"traces",
         {{{"id", "T1"},
           {"photo", "right"},
           {"ends", {{-3, 500}, {800, 900}}},
           {"cost", "darkness"}}}}},
       "picks.traces[0].ends[0]",
       "is outside the right photograph"},
      {{{"traces",
         {{{"id", "T1"},
           {"photo", "right"},
           {"ends", {{30, 500}, {800, 900}}},
           {"cost", "curvature"}}}}},
       "picks.traces[0].cost",
       "left photograph only"},
      {{{"areas",
         {{{"id", "A1"},
           {"pair", 2},
           {"photo", "left"},
           {"polygon", {{100, 100}, {300, height + 1}, {200, 50}}}}}}},
       "picks.areas[0].polygon[1]",
       "is outside the pair 2 left photograph"},
      {{{"points", {{{"id", "Q1"}, {"photo", "left"}, {"pixel", {10, -20}}}}}},
       "picks.points[0].pixel[0]",
       "is outside the left photograph"}};
  for (const Bad& b : bad) {
    nlohmann::json s = scene;
    s["picks"] = b.picks;
    std::ofstream(file) << s.dump(2);
    for (const fs::path& project : {fresh, existing}) {
      const CliRun r = run_rockface("replay " + file.string() + " --project " + project.string() +
                                    " --preset fast");
      EXPECT_EQ(r.exit_code, 2) << b.where << ": " << r.err;
      EXPECT_NE(r.err.find(file.string() + ": " + b.where + ": "), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(b.what), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(fresh)) << b.where;
    EXPECT_EQ(bytes(existing), before) << b.where;
  }
  EXPECT_FALSE(fs::exists(fs::path(fresh.string() + ".spool")));
}

TEST(PicksPair, TheParserNamesABadPair) {
  auto error_of = [](const nlohmann::json& trace) {
    const nlohmann::json doc = {{"format", "rockface-picks/1"}, {"traces", {trace}}};
    try {
      rockface::storage::parse_picks(doc.dump(), "PICKS.json");
    } catch (const rockface::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const nlohmann::json taps = {{"id", "T1"}, {"photo", "left"}, {"pixels", {{1, 2}, {3, 4}}}};
  nlohmann::json t = taps;
  EXPECT_EQ(error_of(t), "accepted");
  t["pair"] = 2;
  EXPECT_EQ(error_of(t), "accepted");
  EXPECT_EQ(rockface::storage::parse_picks(
                nlohmann::json({{"format", "rockface-picks/1"}, {"traces", {t}}}).dump(), "P")
                .traces[0]
                .pair,
            2);
  t["pair"] = 0;
  EXPECT_EQ(error_of(t), "PICKS.json: traces[0].pair: pairs are counted from 1");
  t["pair"] = 1.5;
  EXPECT_EQ(error_of(t), "PICKS.json: traces[0].pair: must be a whole number");
  t = taps;
  t["pair"] = 2;
  t["photo"] = "right";
  EXPECT_NE(error_of(t).find("traces[0].photo: a further pair's trace is tapped in its left"),
            std::string::npos);
  // Areas and points take a pair too, a further one in its left photograph.
  auto error_of_doc = [](const nlohmann::json& doc) {
    try {
      rockface::storage::parse_picks(doc.dump(), "PICKS.json");
    } catch (const rockface::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  nlohmann::json area = {
      {"id", "A1"}, {"pair", 3}, {"photo", "left"}, {"polygon", {{1, 2}, {3, 4}, {5, 1}}}};
  nlohmann::json point = {{"id", "Q1"}, {"pair", 2}, {"photo", "left"}, {"pixel", {1, 2}}};
  const auto parsed = rockface::storage::parse_picks(
      nlohmann::json({{"format", "rockface-picks/1"}, {"areas", {area}}, {"points", {point}}})
          .dump(),
      "P");
  EXPECT_EQ(parsed.areas[0].pair, 3);
  EXPECT_EQ(parsed.points[0].pair, 2);
  area["pair"] = 0;
  EXPECT_EQ(error_of_doc({{"format", "rockface-picks/1"}, {"areas", {area}}}),
            "PICKS.json: areas[0].pair: pairs are counted from 1");
  point["photo"] = "right";
  EXPECT_EQ(error_of_doc({{"format", "rockface-picks/1"}, {"points", {point}}}),
            "PICKS.json: points[0].photo: a further pair's pick is made in its left photograph");
  point.erase("pair");
  EXPECT_EQ(rockface::storage::parse_picks(
                nlohmann::json({{"format", "rockface-picks/1"}, {"points", {point}}}).dump(), "P")
                .points[0]
                .pair,
            1);
  const nlohmann::json ends = {
      {"id", "T1"}, {"pair", 2}, {"photo", "left"}, {"ends", {{1, 2}, {3, 4}}}};
  EXPECT_NE(error_of(ends).find("traces[0].pair: a further pair's trace is given as taps"),
            std::string::npos);
}
