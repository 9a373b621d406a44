// A face of three joint sets of known spacing, rendered by the mock camera
// (the demo face, its stereo pair at the demo's 1500 x 1000), its traces
// tapped in the left photograph where the renderer drew them (truth.json),
// replayed at the standard preset: the traces are measured on the reconstructed
// 3D image. The rock-mass figures of the visit against the truth's: the
// spacing of the mapped joints' true planes, the Jv they make, and the RQD
// of the same scanlines over the true traces.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "camera/synthetic_renderer.h"
#include "core/geometry/orientation.h"
#include "core/rockmass/figures_in_words.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
#include "firmware-app/rockmass/visit_rock_mass.h"
#include "storage/project/project_store.h"
#include "storage/scene/scene.h"
#include "tests/support/cli_run.h"
#include "tests/support/truth_picks.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct TrueSet {
  std::string label;
  double dip, dipdir, spacing;
};
// The demo's three sets at spacings of about a metre: a dozen joints and
// their traces over the 6 x 5 m face.
const TrueSet kSets[] = {{"S1", 60, 200, 0.9}, {"S2", 75, 110, 1.1}, {"S3", 20, 350, 1.3}};

class RockMassFace : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rockface-rockmass-face-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    json scene = test::demo_scene();
    const Eigen::Vector3d centre(512340.0, 5211880.3, 412.5);
    std::vector<Eigen::Vector3d> corners;
    for (const auto& patch : scene["surface"]["patches"])
      if (patch["id"].get<std::string>().rfind("FACE", 0) == 0)
        for (const auto& p : patch["polygon"])
          corners.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    json joints = json::array();
    for (const auto& s : kSets) {
      const Eigen::Vector3d n = geometry::plane_normal_deg(s.dip, s.dipdir);
      double lo = 1e9, hi = -1e9;
      for (const auto& c : corners) {
        lo = std::min(lo, n.dot(c - centre));
        hi = std::max(hi, n.dot(c - centre));
      }
      // Offsets a third of a spacing off the centre: no joint through the
      // sets' common point.
      for (int j = static_cast<int>(std::floor(lo / s.spacing));
           j <= static_cast<int>(std::ceil(hi / s.spacing)); ++j) {
        const double d = (j + 0.37) * s.spacing;
        if (d <= lo || d >= hi) continue;
        const Eigen::Vector3d p = centre + d * n;
        const std::string id = "J" + std::to_string(joints.size() + 1);
        joints.push_back({{"id", id},
                          {"dip", s.dip},
                          {"dipdir", s.dipdir},
                          {"point", {p.x(), p.y(), p.z()}},
                          {"friction", 30},
                          {"cohesion", 0}});
        true_set_[id] = &s - kSets;
        offset_[id] = d;
      }
    }
    scene["joints"] = joints;
    // The standard preset: at the fast one the 3D image has holes under
    // taps beside the range pole and the photograph's borders, which the
    // replay refuses (as tests/integration/replay/replay_face_picks_test.cpp
    // found); the picture stays small (the demo's 1500 x 1000).
    scene["analysis"] = {{"blocks", true}, {"preset", "standard"}};
    std::ofstream(dir_ / "face.scene.json") << scene.dump(2);
    const test::CliRun render = test::run_rockface("render " + (dir_ / "face.scene.json").string() +
                                                   " --out " + (dir_ / "render").string());
    ASSERT_EQ(render.exit_code, 0) << render.err;
    // The range pole stands 2 m before the face: the face behind it is not
    // in the 3D image, and a tap there is refused. Its box in the left
    // photograph (pinhole projection of its shaft, widened by its targets
    // and 60 px for the lens distortion and the dense matching's edge).
    const auto& imaging = scene["imaging"];
    const auto& st = imaging["stations"][0];
    const auto& cam = imaging["camera"];
    const Eigen::Vector3d eye(st["position"][0].get<double>(), st["position"][1].get<double>(),
                              st["position"][2].get<double>());
    const Eigen::Vector3d look(st["look_at"][0].get<double>(), st["look_at"][1].get<double>(),
                               st["look_at"][2].get<double>());
    const Eigen::Vector3d fwd = (look - eye).normalized();
    const Eigen::Vector3d right = fwd.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d down = fwd.cross(right);
    const auto& pole = imaging["range_pole"];
    const Eigen::Vector3d base(pole["base"][0].get<double>(), pole["base"][1].get<double>(),
                               pole["base"][2].get<double>());
    const double pole_length = pole["length"].get<double>();
    const double reach = pole.value("target_diameter", 0.25);
    double u0 = 1e9, u1 = -1e9, v0 = 1e9, v1 = -1e9;
    for (double f = 0; f <= 1.0001; f += 0.05)
      for (double side : {-reach, reach}) {
        const Eigen::Vector3d q = base + Eigen::Vector3d(0, 0, f * pole_length) + side * right;
        const double z = (q - eye).dot(fwd);
        const double u =
            cam["cx"].get<double>() + cam["fx"].get<double>() * (q - eye).dot(right) / z;
        const double v =
            cam["cy"].get<double>() + cam["fy"].get<double>() * (q - eye).dot(down) / z;
        u0 = std::min(u0, u - 60);
        u1 = std::max(u1, u + 60);
        v0 = std::min(v0, v - 60);
        v1 = std::max(v1, v + 60);
      }
    json picks = json::array();
    for (auto t : test::face_traces(dir_ / "render" / "truth.json")) {
      // The longest run of the trace's pixels clear of the pole.
      std::size_t best_from = 0, best_n = 0;
      for (std::size_t i = 0; i < t.pixels.size();) {
        auto behind = [&](std::size_t k) {
          return t.pixels[k][0] > u0 && t.pixels[k][0] < u1 && t.pixels[k][1] > v0 &&
                 t.pixels[k][1] < v1;
        };
        if (behind(i)) {
          ++i;
          continue;
        }
        std::size_t j = i;
        while (j < t.pixels.size() && !behind(j)) ++j;
        if (j - i > best_n) {
          best_from = i;
          best_n = j - i;
        }
        i = j;
      }
      t.pixels.assign(t.pixels.begin() + static_cast<long>(best_from),
                      t.pixels.begin() + static_cast<long>(best_from + best_n));
      if (t.pixels.size() < 20) continue;
      // The taps keep 8 % off each end, away from the photograph's borders
      // where dense matching leaves holes. The true traces below span what
      // was measured.
      const std::size_t cut = t.pixels.size() * 8 / 100;
      t.pixels.assign(t.pixels.begin() + cut, t.pixels.end() - cut);
      picked_.insert({t.joint, t.patch});
      pick_of_["T" + std::to_string(picks.size() + 1)] = {t.joint, t.patch};
      picks.push_back({{"id", "T" + std::to_string(picks.size() + 1)},
                       {"joint", t.joint},
                       {"photo", "left"},
                       {"pixels", test::taps_along(t, 8)}});
    }
    scene["picks"] = {{"traces", picks}};
    // What the geologist entered on site comes with the scene.
    scene["rockmass"] = {{"ucs_mpa", 120}, {"groundwater", "damp"}, {"Jr", 1.5}, {"Ja", 1.0}};
    std::ofstream(dir_ / "face.scene.json") << scene.dump(2);
    const test::CliRun replay =
        test::run_rockface("replay " + (dir_ / "face.scene.json").string() + " --project " +
                           (dir_ / "face.rockface").string());
    ASSERT_EQ(replay.exit_code, 0) << replay.err << replay.out;
    std::printf("%zu joints, %zu traces picked\n", joints.size(), picks.size());
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static inline fs::path dir_;
  static inline std::map<std::string, int> true_set_;                   // joint -> index in kSets
  static inline std::map<std::string, double> offset_;                  // joint -> n . (p - centre)
  static inline std::set<std::pair<std::string, std::string>> picked_;  // (joint, patch)
  static inline std::map<std::string, std::pair<std::string, std::string>> pick_of_;  // id -> that
};

// The measured set that matches true set k: the nearest mean pole.
int matching_set(const rockmass::RockMassInput& in, int k) {
  const Eigen::Vector3d n = geometry::plane_normal_deg(kSets[k].dip, kSets[k].dipdir);
  int best = -1;
  double best_cos = 0;
  for (std::size_t i = 0; i < in.sets.size(); ++i) {
    const double c = std::abs(in.sets[i].normal.dot(n));
    if (c > best_cos) {
      best_cos = c;
      best = static_cast<int>(i);
    }
  }
  return best_cos > std::cos(10 * M_PI / 180) ? best : -1;
}

TEST_F(RockMassFace, SpacingJvAndRqdAgainstTheTruth) {
  storage::ProjectStore store = storage::ProjectStore::open(dir_ / "face.rockface");
  const auto visit = store.latest_visit();
  ASSERT_TRUE(visit);
  const rockmass::RockMassInput in = visit_rock_mass_input(*&store, *visit);
  const rockmass::RockMassFigures f = rockmass::rock_mass_figures(in);
  for (const auto& line : rockmass::figures_lines(f)) {
    std::printf("%s\n", line.c_str());
    // Units as every screen and the report write them (issue 39): m², m³.
    EXPECT_EQ(line.find(" m3"), std::string::npos) << line;
    EXPECT_EQ(line.find(" m2"), std::string::npos) << line;
  }
  ASSERT_EQ(f.sets, 3);

  // The truth of what was mapped: the true planes of the joints picked,
  // their gaps along the true normal.
  double jv_truth = 0, jv_bound = 0;
  std::vector<double> truth_spacing(3, 0);
  for (int k = 0; k < 3; ++k) {
    std::vector<double> at;
    std::set<std::string> seen;
    for (const auto& [joint, patch] : picked_)
      if (true_set_.at(joint) == k && seen.insert(joint).second) at.push_back(offset_.at(joint));
    std::sort(at.begin(), at.end());
    ASSERT_GE(at.size(), 3u) << kSets[k].label;
    truth_spacing[k] = (at.back() - at.front()) / static_cast<double>(at.size() - 1);
    const int m = matching_set(in, k);
    ASSERT_GE(m, 0) << kSets[k].label << " not found among the measured sets";
    const auto& s = f.spacings[m];
    ASSERT_TRUE(s.mean_m) << s.label;
    EXPECT_EQ(s.discontinuities, static_cast<int>(at.size())) << s.label;
    // Expected error: each trace's position along the normal carries the
    // 3D image's error at the standard preset (~1-2 cm at 10 m) plus the set's
    // mean pole error (~1 deg) over the half-face lever (~3 m: ~5 cm); the
    // mean gap is the span over (k - 1) gaps, so two ends' errors over the
    // span, and the range pole's scale (~1 %): 0.1 m / (k - 1) + 2 %.
    const double tol = 0.1 / static_cast<double>(at.size() - 1) + 0.02 * truth_spacing[k];
    std::printf("%s: measured %.3f m, truth %.3f m (design %.2f), tolerance %.3f\n",
                kSets[k].label.c_str(), *s.mean_m, truth_spacing[k], kSets[k].spacing, tol);
    EXPECT_NEAR(*s.mean_m, truth_spacing[k], tol) << s.label;
    jv_truth += 1 / truth_spacing[k];
    jv_bound += tol / (truth_spacing[k] * (truth_spacing[k] - tol));
  }
  ASSERT_TRUE(f.jv.jv);
  // The spacings' tolerances carried into sum 1/S (no random traces in truth:
  // any the measurement leaves unassigned add their term, stated).
  std::printf("Jv measured %.3f, truth %.3f, bound %.3f, random %.3f\n", *f.jv.jv, jv_truth,
              jv_bound, f.jv.from_random);
  EXPECT_NEAR(f.jv.from_sets, jv_truth, jv_bound);
  EXPECT_TRUE(f.assigned.random.empty()) << f.assigned.random.size() << " traces of no set";

  // RQD: the same scanlines in the same window over the true traces of the
  // joints that were picked (each on its facet).
  const storage::Scene scene = storage::load_scene((dir_ / "face.scene.json").string());
  const SyntheticSceneInput synthetic = synthetic_scene_from_scene(scene);
  std::vector<rockmass::FaceTrace> truth;
  std::vector<rockmass::SetInput> truth_sets;
  for (int k = 0; k < 3; ++k)
    truth_sets.push_back(
        {kSets[k].label, geometry::plane_normal_deg(kSets[k].dip, kSets[k].dipdir)});
  // Each measured trace's true line over the same extent: its (joint,
  // facet)'s true segment cut to where the measured points project on it.
  const auto segments = camera::true_trace_segments(synthetic.scene);
  for (const auto& m : store.list_measurements(*visit)) {
    if (m.kind != storage::Measurement::Kind::trace || !pick_of_.count(m.label)) continue;
    const auto& [joint, patch] = pick_of_.at(m.label);
    for (const auto& seg : segments) {
      if (seg.joint != joint || seg.patch != patch) continue;
      const Eigen::Vector3d a = seg.world[0] + synthetic.origin - scene.datum;
      const Eigen::Vector3d d = seg.world[1] - seg.world[0];
      double lo = 1, hi = 0;
      for (const auto& p : m.points) {
        const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
      }
      if (hi <= lo) continue;
      rockmass::FaceTrace t;
      t.label = m.label;
      t.joint_label = joint;
      t.set_label = kSets[true_set_.at(joint)].label;
      t.points = {a + lo * d, a + hi * d};
      truth.push_back(t);
    }
  }
  const rockmass::SetTraces assigned = rockmass::assign_traces_to_sets(truth, truth_sets, f.window);
  const auto spacings = rockmass::set_spacings(truth, truth_sets, assigned, f.window);
  const rockmass::ScanlineRqd truth_rqd =
      rockmass::scanline_rqd(truth, assigned, truth_sets, spacings, f.window);
  ASSERT_TRUE(truth_rqd.rqd_percent);
  ASSERT_TRUE(f.scanlines.rqd_percent);
  for (std::size_t d = 0; d < 3; ++d) {
    const auto& m = f.scanlines.directions[d];
    const auto& t = truth_rqd.directions[d];
    std::printf("%s: RQD measured %.1f %%, truth %.1f %%; crossings %d / %d; Priest-Hudson %.1f\n",
                m.name.c_str(), *m.rqd_percent, *t.rqd_percent, m.crossings, t.crossings,
                *m.priest_hudson_from_spacing);
    // A crossing moves by the trace's position error (< 5 cm, above), so
    // only pieces within 5 cm of Deere's 0.1 m change sides; at about two
    // crossings per metre (exponential pieces) they hold under 5 % of a
    // line's length; and a trace's end may stop short of a line that the
    // true trace crosses (taps end up to a few cm inside): 5 points.
    EXPECT_NEAR(*m.rqd_percent, *t.rqd_percent, 5.0) << m.name;
    // The same count of crossings but for those ends: one per line.
    EXPECT_NEAR(m.crossings, t.crossings, m.lines) << m.name;
  }

  // The form came with the scene: stored with the visit.
  const auto stored = store.load_rockmass_form(*visit);
  ASSERT_TRUE(stored);
  EXPECT_EQ(*stored->jr, 1.5);
  EXPECT_EQ(*stored->groundwater, rockmass::Groundwater::damp);
}

TEST_F(RockMassFace, AnEmptyFormFillsTheMeasuredLinesAndNoTotal) {
  storage::ProjectStore store = storage::ProjectStore::open(dir_ / "face.rockface");
  const auto visit = store.latest_visit();
  const rockmass::RockMassFigures f =
      visit_rock_mass(store, *visit, rockmass::ClassificationForm{});
  for (const auto& line : rockmass::classification_lines(f)) std::printf("%s\n", line.c_str());
  EXPECT_EQ(f.rmr.rqd.source, rockmass::Source::measured);
  EXPECT_EQ(f.rmr.spacing.source, rockmass::Source::measured);
  EXPECT_EQ(f.q.rqd.source, rockmass::Source::measured);
  EXPECT_EQ(f.q.jn.source, rockmass::Source::measured);
  EXPECT_EQ(*f.q.jn.rating, 9);  // three sets
  EXPECT_EQ(f.rmr.strength.source, rockmass::Source::not_entered);
  EXPECT_EQ(f.rmr.groundwater.source, rockmass::Source::not_entered);
  EXPECT_EQ(f.q.jr.source, rockmass::Source::not_entered);
  EXPECT_FALSE(f.rmr.adjusted.value);
  EXPECT_FALSE(f.rmr.basic.value);
  EXPECT_FALSE(f.q.q);
  EXPECT_NE(rockmass::rmr_line(f.rmr).find("incomplete"), std::string::npos);
  EXPECT_NE(rockmass::q_line(f.q).find("incomplete"), std::string::npos);
}

TEST_F(RockMassFace, TheVerbWritesTheFiguresAndRefusesAFormOutOfRangeByName) {
  const fs::path project = dir_ / "face.rockface";
  const fs::path out = dir_ / "rockmass.json";
  test::CliRun r = test::run_rockface("rockmass " + project.string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out);
  const json j = json::parse(in);
  EXPECT_EQ(j["format"], "rockface-rockmass/1");
  EXPECT_EQ(j["sets"].size(), 3u);
  EXPECT_EQ(j["rmr89"]["strength"]["source"], "entered");  // the scene's form, stored
  EXPECT_EQ(j["rmr89"]["rqd"]["source"], "measured");
  EXPECT_FALSE(j["q"]["complete"].get<bool>());  // Jw and SRF not entered

  std::ofstream(dir_ / "bad-form.json") << R"({"Jr": 1.5, "Ja": 30})";
  r = test::run_rockface("rockmass " + project.string() + " --form " +
                         (dir_ / "bad-form.json").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("Ja"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0.75-20"), std::string::npos) << r.err;

  std::ofstream(dir_ / "form.json") << R"({"Jr": 1.5, "Ja": 1, "Jw": 1, "SRF": 1})";
  r = test::run_rockface("rockmass " + project.string() + " --form " +
                         (dir_ / "form.json").string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in2(out);
  const json k = json::parse(in2);
  EXPECT_TRUE(k["q"]["complete"].get<bool>());
  EXPECT_EQ(k["q"]["jn"]["source"], "measured");
}

}  // namespace
}  // namespace rockface::app
