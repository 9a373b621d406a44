// Trace proposals on the Mapping screen (issue 25) through `rockface ui
// --headless --script`: on the demo project, Find traces, tap a proposal on
// the model, Accept; then run the analysis. The demo's three joints are
// mapped by hand already, so the proposals along them (P1, P2, P4) are
// hidden as already mapped: P3, a dark line nobody mapped, is the one left
// to decide. The accepted
// proposal is stored as a trace with origin "proposed", its points on the
// model and its pixels in the left photograph, and the analysis reads it
// exactly as it reads a trace tapped by hand (the scene of the visit lists
// it among its traces, with its points). A rejected proposal stores nothing.
#include <fstream>

#include <gtest/gtest.h>

#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "tests/ui/demo_project.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface::test;

TEST(UiProposals, AnAcceptedProposalIsStoredAndAnalysedLikeAHandTrace) {
  const fs::path project = copy_of_demo("proposals");
  std::size_t measurements = 0, analyses = 0;
  {
    auto store = rockface::storage::ProjectStore::open(project);
    measurements = store.list_measurements().size();
    analyses = store.list_analyses().size();
  }
  ASSERT_EQ(run_demo_script(project, R"([
      {"tap": "Mapping"}, {"wait": "task"}, {"tap": "Find traces"}, {"wait": "task"}, {"frames": 2},
      {"screenshot": "proposals"}, {"tap": "proposal P3"}, {"frames": 1},
      {"screenshot": "selected"}, {"tap": "Accept"}, {"wait": "task"},
      {"tap": "Blocks"}, {"tap": "Run analysis"}, {"wait": "task"}])",
                            "accept"),
            0)
      << slurp(ui_test_dir() / "accept.txt");
  const std::string out = slurp(ui_test_dir() / "accept.txt");
  EXPECT_TRUE(fs::exists(ui_test_dir() / "accept" / "selected.png")) << out;

  auto store = rockface::storage::ProjectStore::open(project);
  const auto stored = store.list_measurements();
  ASSERT_EQ(stored.size(), measurements + 1) << out;
  const auto& t = stored.back();
  EXPECT_EQ(t.kind, rockface::storage::Measurement::Kind::trace);
  EXPECT_EQ(t.origin, "proposed");
  EXPECT_EQ(t.label[0], 'T');  // numbered on with the hand traces
  EXPECT_EQ(t.photo, "left");
  EXPECT_TRUE(t.photo_capture_id.has_value());
  EXPECT_GE(t.pixels.size(), 2u);
  // A proposal is at least the fast preset's 30 cm long (the demo face is
  // ~10 m away: a proposal shorter than that was not kept).
  ASSERT_TRUE(t.trace_length_m.has_value());
  EXPECT_GE(*t.trace_length_m, 0.3);
  EXPECT_GE(t.points.size(), 2u);
  // Every earlier trace was tapped by hand.
  for (std::size_t i = 0; i + 1 < stored.size(); ++i) EXPECT_EQ(stored[i].origin, "hand");

  // The analysis read it as it reads a hand trace: the scene of the visit
  // lists it with its points.
  const auto runs = store.list_analyses();
  ASSERT_EQ(runs.size(), analyses + 1) << out;
  EXPECT_FALSE(store.load_analysis(runs.back().id).blocks.empty());
  const nlohmann::json scene =
      rockface::storage::make_scene_json(rockface::storage::load_scene_source(store, t.visit_id));
  bool listed = false;
  for (const auto& s : scene.at("traces"))
    if (s.at("id") == t.label) {
      listed = true;
      EXPECT_EQ(s.at("points").size(), t.points.size());
    }
  EXPECT_TRUE(listed) << t.label << " is not among the analysed traces";
}

TEST(UiProposals, ARejectedProposalStoresNothing) {
  const fs::path project = copy_of_demo("proposals-reject");
  std::size_t measurements = 0;
  {
    auto store = rockface::storage::ProjectStore::open(project);
    measurements = store.list_measurements().size();
  }
  ASSERT_EQ(run_demo_script(project, R"([
      {"tap": "Mapping"}, {"wait": "task"}, {"tap": "Find traces"}, {"wait": "task"}, {"frames": 2},
      {"tap": "P3"}, {"frames": 1}, {"tap": "Reject"}, {"frames": 2},
      {"screenshot": "rejected"}])",
                            "reject"),
            0)
      << slurp(ui_test_dir() / "reject.txt");
  auto store = rockface::storage::ProjectStore::open(project);
  EXPECT_EQ(store.list_measurements().size(), measurements);
}

}  // namespace
