// A whole session through `rockface ui --headless --script`: open the demo
// project, mark a trace by taps, run the analysis, take a stereo pair with the mock camera, start
// its reconstruction and cancel it, close; then reopen. What finished is in
// the store; what was cancelled left nothing half-written.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "storage/project/project_store.h"
#include "tests/ui/demo_project.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface::test;

TEST(UiSession, FinishedStepsAreStoredAndACancelledRunLeavesNothingHalfDone) {
  const fs::path project = copy_of_demo("session");
  std::size_t analyses = 0, captures = 0, models = 0, measurements = 0;
  {
    auto store = rockface::storage::ProjectStore::open(project);
    measurements = store.list_measurements().size();
    analyses = store.list_analyses().size();
    captures = store.list_captures().size();
    models = store.list_models().size();
  }
  // The taps lie on the face in the 800 x 500 layout at scale 0.6 (the
  // model panel's middle).
  ASSERT_EQ(run_demo_script(project, R"([
      {"tap": "Mapping"}, {"tap": [250, 230]}, {"tap": [280, 250]}, {"tap": [310, 270]},
      {"screenshot": "mapping"}, {"tap": "Save trace"}, {"wait": "task"},
      {"tap": "Blocks"}, {"tap": "Run analysis"}, {"wait": "task"}, {"screenshot": "blocks"},
      {"tap": "Capture"}, {"tap": "Connect camera"}, {"wait": "task"},
      {"tap": "Shoot left"}, {"wait": "task"}, {"tap": "Shoot right"}, {"wait": "task"},
      {"tap": "Store pair and reconstruct"}, {"frames": 2}, {"tap": "Stop 3D images"}, {"wait": "task"},
      {"screenshot": "capture"}, {"tap": "Project"}, {"tap": "Close project"}])",
                            "first"),
            0)
      << slurp(ui_test_dir() / "first.txt");
  const std::string out = slurp(ui_test_dir() / "first.txt");
  EXPECT_NE(out.find("screenshot"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists(ui_test_dir() / "first" / "capture.png"));

  {
    auto store = rockface::storage::ProjectStore::open(project);
    EXPECT_TRUE(store.check_integrity().ok);
    const auto traces = store.list_measurements();
    ASSERT_EQ(traces.size(), measurements + 1);  // the trace marked by taps
    EXPECT_EQ(traces.back().points.size(), 3u);
    const auto runs = store.list_analyses();
    ASSERT_EQ(runs.size(), analyses + 1);  // the analysis run in the UI
    EXPECT_FALSE(store.load_analysis(runs.back().id).blocks.empty());
    EXPECT_EQ(store.list_captures().size(),
              captures + 1);                        // the pair, stored before reconstructing
    EXPECT_EQ(store.list_models().size(), models);  // the cancelled reconstruction
  }

  // Reopen: the Blocks table holds the stored analysis (a row can be tapped).
  ASSERT_EQ(run_demo_script(
                project, R"([{"tap": "Blocks"}, {"tap": "row TB1"}, {"screenshot": "reopened"}])",
                "second"),
            0)
      << slurp(ui_test_dir() / "second.txt");
  EXPECT_TRUE(fs::exists(ui_test_dir() / "second" / "reopened.png"));
}

// The points every `step` metres along a polyline, between fractions
// [from, to] of its length.
std::vector<Eigen::Vector3d> along(const std::vector<Eigen::Vector3d>& line, double from, double to,
                                   double step) {
  std::vector<double> at{0};
  for (std::size_t k = 1; k < line.size(); ++k)
    at.push_back(at.back() + (line[k] - line[k - 1]).norm());
  std::vector<Eigen::Vector3d> out;
  for (double s = from * at.back(); s <= to * at.back() + 1e-9; s += step) {
    std::size_t k = 1;
    while (k + 1 < line.size() && at[k] < s) ++k;
    const double f = (s - at[k - 1]) / std::max(at[k] - at[k - 1], 1e-12);
    out.push_back(line[k - 1] + std::clamp(f, 0.0, 1.0) * (line[k] - line[k - 1]));
  }
  return out;
}

// The tablet's analysis of a visit whose joint trace was marked in two
// pieces on two pairs (stored with different models, as the Mapping screen
// stores a trace on its chosen pair): the analysis takes them as one trace
// and logs which stored traces it joined.
TEST(UiSession, TheAnalysisJoinsPiecesOfATraceStoredFromTwoPairs) {
  const fs::path project = copy_of_demo("pieces");
  std::size_t analyses = 0;
  std::string label;  // of the stored trace the pieces are cut from
  {
    auto store = rockface::storage::ProjectStore::open(project);
    const auto visit = store.latest_visit();
    ASSERT_TRUE(visit);
    analyses = store.list_analyses().size();
    // A second 3D image to store the second piece with: the visit's model
    // stored again (what is checked is that the pieces' models differ).
    const auto models = store.list_models();
    ASSERT_FALSE(models.empty());
    const rockface::storage::RecordId second = store.save_model(store.load_model(models[0].id));
    // A joint's stored trace, marked again as two pieces overlapping on 20 %
    // of it: the first 60 % on pair 1, the last 60 % on pair 2.
    std::optional<rockface::storage::Measurement> whole;
    for (const auto& m : store.list_measurements(*visit))
      if (m.kind == rockface::storage::Measurement::Kind::trace && !m.joint_label.empty() &&
          m.model_id && m.points.size() >= 2) {
        whole = m;
        break;
      }
    ASSERT_TRUE(whole);
    label = whole->label;
    rockface::storage::Measurement a = *whole, b = *whole;
    a.id = b.id = 0;
    a.label = "X1";
    a.points = along(whole->points, 0.0, 0.6, 0.05);
    b.label = "X2";
    b.model_id = second;
    b.points = along(whole->points, 0.4, 1.0, 0.05);
    store.save_measurements(*visit, {a, b});
  }
  ASSERT_EQ(
      run_demo_script(project, R"([{"tap": "Blocks"}, {"tap": "Run analysis"}, {"wait": "task"}])",
                      "pieces"),
      0)
      << slurp(ui_test_dir() / "pieces.txt");
  auto store = rockface::storage::ProjectStore::open(project);
  const auto runs = store.list_analyses();
  ASSERT_EQ(runs.size(), analyses + 1);
  const std::string action = "analysis " + std::to_string(runs.back().id) + " joined traces";
  std::string detail;
  for (const auto& e : store.list_actions(store.latest_visit()))
    if (e.action == action) detail = e.detail;
  // X2 (pair 2) continues both X1 and the stored trace it was cut from
  // (pair 1); those two, on one pair, are joined only through it: one
  // trace, named after the first stored piece.
  EXPECT_EQ(detail, label + " = " + label + " X1 X2");
}

// Issue 27: a whole visit in few taps, the committed script that also makes
// the README's pictures (docs/ui-visit.steps.json, 1280 x 800): new visit,
// both shots, the 3D image, the face's outline (four corners), three traces
// (the third semi-automatic, from its two ends), each with its joint when
// its plane is known, the analysis and the field report holding them.
// Each step is stored;
// the taps and the time on each screen are printed for
// docs/accuracy-cost.md.
TEST(UiSession, AWholeVisitInFewTaps) {
  const fs::path project = copy_of_demo("visit");
  const fs::path shots = ui_test_dir() / "visit";
  const fs::path settings = ui_test_dir() / "visit-settings.json";
  const fs::path log = ui_test_dir() / "visit.txt";
  ASSERT_EQ(run_rockface_logged("ui --project " + project.string() + " --camera " + demo_scene() +
                                    " --settings " + settings.string() +
                                    " --max-triangles 20000 --headless --script " +
                                    std::string(ROCKFACE_SOURCE_DIR) +
                                    "/docs/ui-visit.steps.json --screenshots " + shots.string(),
                                log),
            0)
      << slurp(log);
  const std::string out = slurp(log);
  std::printf("%s", out.c_str());
  auto store = rockface::storage::ProjectStore::open(project);
  const auto visits = store.list_visits();
  ASSERT_EQ(visits.size(), 2u);  // the demo's and the new one
  const auto visit = visits.back().id;
  EXPECT_EQ(store.list_captures(visit).size(), 1u);
  EXPECT_EQ(store.list_models().size(), 2u);  // the new visit's 3D image
  std::vector<rockface::storage::Measurement> traces;
  for (const auto& m : store.list_measurements(visit))
    if (m.kind == rockface::storage::Measurement::Kind::trace) traces.push_back(m);
  ASSERT_EQ(traces.size(), 3u);
  EXPECT_EQ(traces[0].points.size(), 3u);  // tapped point by point
  EXPECT_EQ(traces[1].points.size(), 3u);
  // The semi-automatic one follows the joint between its two ends: many
  // more points than taps.
  EXPECT_GT(traces[2].points.size(), 10u);
  // The face outlined on the tablet is the visit's mapped face, stored as
  // the flat pieces of the 3D image it covers (issue 27): the demo face is
  // folded, two walls 11.5° apart, and the four corners span the fold, so
  // two areas, F1a and F1b, no free face.
  std::vector<rockface::storage::Measurement> areas;
  for (const auto& m : store.list_measurements(visit))
    if (m.kind == rockface::storage::Measurement::Kind::area) areas.push_back(m);
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_EQ(areas[0].label, "F1a");
  EXPECT_EQ(areas[1].label, "F1b");
  for (const auto& a : areas) {
    EXPECT_TRUE(a.rock_side.empty()) << a.label;
    EXPECT_GE(a.points.size(), 3u) << a.label;
  }
  const auto joints = store.list_joints(visit);
  std::size_t known = 0;
  for (const auto& t : traces) {
    known += t.dip_deg.has_value();
    const bool has_joint = std::any_of(joints.begin(), joints.end(), [&](const auto& j) {
      return j.label == t.label && j.measurement_id == t.id;
    });
    EXPECT_EQ(has_joint, t.dip_deg.has_value()) << t.label;
  }
  EXPECT_EQ(joints.size(), known);
  // The two tapped traces cross the demo face's one fold (so their planes
  // are known: joints); the semi-automatic one does not (a straight line
  // on one flat face), so the geologist gave it the compass reading of its
  // joint, J2 (the scene's 75° / 110°, read as 74° / 111°): its joint is
  // that reading, and says so.
  EXPECT_EQ(known, 3u);
  ASSERT_TRUE(traces[2].dip_deg && traces[2].compass_dip_deg && traces[2].compass_dipdir_deg);
  EXPECT_EQ(*traces[2].compass_dip_deg, 74);
  EXPECT_EQ(*traces[2].compass_dipdir_deg, 111);
  // The stored plane is the reading (degrees to radians and back: ~1e-14).
  EXPECT_NEAR(*traces[2].dip_deg, 74, 1e-9);
  EXPECT_NEAR(*traces[2].dipdir_deg, 111, 1e-9);
  for (const auto& j : joints)
    if (j.label == traces[2].label) {
      EXPECT_EQ(j.source, "trace " + j.label + " (compass)");
    }
  // The analysis of the visit made only on the tablet, with its face (the
  // two flat pieces) and its three joints: the traces lie on the pieces
  // (within the 0.05 m snap tolerance), so the trace map has them and the
  // three joints cut the face into at least one finite block.
  const auto runs = store.list_analyses(visit);
  ASSERT_EQ(runs.size(), 1u);
  const auto run = store.load_analysis(runs[0].id);
  std::size_t finite = 0;
  for (const auto& b : run.blocks) {
    // The stored mode column: the block's mode, "none" when it has none.
    EXPECT_FALSE((b.mode ? b.mode->type : std::string("none")).empty()) << b.id;
    finite += b.finite;
  }
  EXPECT_GE(finite, 1u) << out;
  // The field report holds them: each block's row and each joint's line
  // (pdftotext, as the report verb's tests read it).
  const fs::path pdf = project.parent_path() / ("visit-visit-" + std::to_string(visit) + ".pdf");
  ASSERT_TRUE(fs::exists(pdf)) << out;
  const fs::path text = ui_test_dir() / "visit-report.txt";
  ASSERT_EQ(std::system(("pdftotext -layout " + pdf.string() + " " + text.string()).c_str()), 0);
  const std::string report = slurp(text);
  auto has_line_starting = [&](const std::vector<std::string>& words) {
    std::istringstream lines(report);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream in(line);
      std::vector<std::string> w;
      for (std::string x; in >> x;) w.push_back(x);
      if (w.size() >= words.size() && std::equal(words.begin(), words.end(), w.begin()))
        return true;
    }
    return false;
  };
  // Each block's row, and for a finite block its volume (m³ to 3 decimals,
  // as the report prints it) and its verdict on that row.
  auto line_starting = [&](const std::vector<std::string>& words) {
    std::istringstream lines(report);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream in(line);
      std::vector<std::string> w;
      for (std::string x; in >> x;) w.push_back(x);
      if (w.size() >= words.size() && std::equal(words.begin(), words.end(), w.begin()))
        return line;
    }
    return std::string();
  };
  for (const auto& b : run.blocks) {
    const std::string row = line_starting({b.id, b.source});
    ASSERT_FALSE(row.empty()) << b.id << " not in\n" << report;
    if (!b.finite) continue;
    char volume[32];
    std::snprintf(volume, sizeof volume, "%.3f", b.volume.value_or(0));
    EXPECT_NE(row.find(volume), std::string::npos) << b.id << ": " << row;
    EXPECT_NE(row.find(b.removable ? "removable" : "finite, keyed"), std::string::npos)
        << b.id << ": " << row;
  }
  // The face outline in words, its two flat pieces.
  EXPECT_NE(report.find("face outline F1: 2 flat pieces, "), std::string::npos) << report;
  auto fixed1 = [](double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.1f", v);
    return std::string(s);
  };
  for (const auto& j : joints)
    EXPECT_TRUE(has_line_starting({j.label, fixed1(j.dip_deg), fixed1(j.dipdir_deg)}))
        << j.label << " not in\n"
        << report;
  // The joint read with a compass says so in the report's joints table.
  EXPECT_NE(report.find("trace " + traces[2].label + " (compass)"), std::string::npos) << report;
  // Few taps: every screen's count is printed, and the whole visit takes at
  // most 39 (30 before issue 27's compass reading: 7 more taps, the two
  // fields and five keys; 2 more since issue 42 for the preset, which this
  // walk sets to fast to stay short: at the default, standard, it is 37).
  for (const char* screen : {"Project", "Capture", "Model", "Mapping", "Blocks"})
    EXPECT_NE(out.find(std::string("screen ") + screen + ": "), std::string::npos) << screen;
  const auto at = out.find("screens in all: ");
  ASSERT_NE(at, std::string::npos) << out;
  EXPECT_LE(std::stoi(out.substr(at + 16)), 39) << out;
  for (const char* picture : {"ui-project", "ui-capture", "ui-model", "ui-mapping", "ui-blocks"})
    EXPECT_TRUE(fs::exists(shots / (std::string(picture) + ".png"))) << picture;
}

}  // namespace

namespace {

TEST(UiCommandLine, WithoutAVerbTheUiStartsAndSaysWhenThereIsNoDisplay) {
  const fs::path log = ui_test_dir() / "no-display.txt";
  EXPECT_EQ(run_rockface_logged("", log, "env -u DISPLAY "), 1);
  EXPECT_NE(slurp(log).find("no display to show the UI on"), std::string::npos) << slurp(log);
  EXPECT_NE(slurp(log).find("--headless"), std::string::npos);
}

TEST(UiCommandLine, ABadScriptStepIsBadInputNamingTheStep) {
  const fs::path script = ui_test_dir() / "bad.json";
  std::ofstream(script) << R"({"steps": [{"tap": "Blocks"}, {"tap": "No such button"}]})";
  const fs::path log = ui_test_dir() / "bad.txt";
  EXPECT_EQ(run_rockface_logged("ui --project " + demo_project().string() +
                                    " --scale 0.6 --max-triangles 20000 --headless --script " +
                                    script.string() + " --screenshots " +
                                    (ui_test_dir() / "bad").string(),
                                log),
            2);
  EXPECT_NE(slurp(log).find("steps[1]: nothing labelled \"No such button\""), std::string::npos)
      << slurp(log);
}

}  // namespace
