// The Mapping screen's blocks (issue 28): after each saved trace the
// tablet updates the blocks of the trace map with faces::TraceSession
// (StoreTraceMapRunner), recomputing only the regions the edit touched. The
// verdicts it shows must be the full analysis's (StoreAnalysisRunner, the
// same workflow as `rockface analyse`) for the same stored traces.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/progress.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "storage/scene/scene.h"
#include "tests/support/dense_face_visit.h"
#include "tests/support/refusal.h"
#include "tests/support/temp_folders.h"
#include "tests/ui/demo_project.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

fs::path test_dir() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("rockface-map-blocks-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    rockface::test::remove_when_passed(d);
    return d;
  }();
  return dir;
}

// The map's verdicts against the stored full analysis of the same traces:
// the same blocks in the same order, the same verdicts, modes and factors of
// safety (the same computation of each region's block, so to the bit; the
// margin to a rounding of the report).
void expect_same_as_full_analysis(const fs::path& file, storage::RecordId visit,
                                  const ui::MapVerdicts& map) {
  NoProgress progress;
  app::StoreAnalysisRunner full;
  const storage::RecordId id = full.analyse(file, visit, progress);
  storage::ProjectStore store = storage::ProjectStore::open(file);
  const storage::AnalysisRun run = store.load_analysis(id);
  std::vector<analysis::ReportBlock> blocks;
  for (const auto& b : run.blocks)
    if (b.source == "traces") blocks.push_back(b);
  ASSERT_EQ(map.blocks.size(), blocks.size());
  for (size_t k = 0; k < blocks.size(); ++k) {
    SCOPED_TRACE("block " + blocks[k].id);
    EXPECT_EQ(map.blocks[k].verdict, analysis::verdict_of(blocks[k]));
    if (!blocks[k].finite) continue;
    EXPECT_EQ(map.blocks[k].mode, blocks[k].mode ? blocks[k].mode->type : "none");
    ASSERT_EQ(map.blocks[k].factor_of_safety.has_value(), blocks[k].fos.has_value());
    if (blocks[k].fos && std::isfinite(*blocks[k].fos)) {
      EXPECT_DOUBLE_EQ(*map.blocks[k].factor_of_safety, *blocks[k].fos);
    }
    const double volume = blocks[k].volume.value_or(0);
    EXPECT_NEAR(map.blocks[k].volume_m3, volume, 1e-9 * volume);
  }
}

TEST(MapBlocks, EachSavedTraceUpdatesOnlyTheTouchedRegionsToTheFullAnalysisVerdicts) {
  const fs::path file = test_dir() / "traced.rockface";
  const test::DenseFace face = test::dense_face(60);
  const storage::RecordId visit = test::make_dense_visit(file, face, 57);
  NoProgress progress;
  app::StoreTraceMapRunner runner;
  const ui::MapVerdicts first = runner.update(file, visit, progress);
  EXPECT_EQ(first.traces, 57);
  EXPECT_EQ(first.reused, 0) << "a new map computes every region";
  ASSERT_GT(first.blocks.size(), 10u);
  int finite = 0;
  for (const auto& b : first.blocks) finite += b.verdict != analysis::BlockVerdict::infinite;
  EXPECT_GT(finite, 0);
  expect_same_as_full_analysis(file, visit, first);
  for (size_t k = 57; k < face.traces.size(); ++k) {
    SCOPED_TRACE("after trace " + face.traces[k].id);
    {
      storage::ProjectStore store = storage::ProjectStore::open(file);
      store.save_measurements(visit, {test::trace_measurement(face.traces[k])});
    }
    const ui::MapVerdicts after = runner.update(file, visit, progress);
    EXPECT_EQ(after.traces, static_cast<int>(k) + 1);
    // One trace of a few metres on a 20 x 10 m face crosses a handful of
    // regions: most blocks are kept.
    EXPECT_GT(after.reused, after.recomputed);
    expect_same_as_full_analysis(file, visit, after);
  }
}

TEST(MapBlocks, AVisitWithoutSurfaceSaysWhatIsMissing) {
  const fs::path file = test_dir() / "no-surface.rockface";
  storage::RecordId visit = 0;
  {
    storage::ProjectStore store = storage::ProjectStore::create(file, {});
    visit = store.begin_visit("tablet");
    storage::Measurement m = test::trace_measurement(test::dense_face(3).traces[0]);
    m.joint_label.clear();
    store.save_measurements(visit, {m});
  }
  NoProgress progress;
  app::StoreTraceMapRunner runner;
  try {
    runner.update(file, visit, progress);
    FAIL() << "a map without a surface has no blocks";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("surface.patches"), std::string::npos) << e.what();
  }
}

// Issue 37: the update builds the analysis input from the rows, no scene
// JSON in between, and refuses what the scene reader refuses in the visit's
// scene export, in the same words.
TEST(MapBlocks, TheUpdateRefusesWhatTheSceneReaderRefusesInItsWords) {
  const fs::path file = test_dir() / "bad-joint.rockface";
  const test::DenseFace face = test::dense_face(8);
  const storage::RecordId visit = test::make_dense_visit(file, face, 8);
  {
    storage::ProjectStore store = storage::ProjectStore::open(file);
    storage::Measurement stray = test::trace_measurement(face.traces[7]);
    stray.label = "T99";
    stray.joint_label = "J404";  // a joint the visit lacks
    store.save_measurements(visit, {stray});
  }
  const std::string name = file.filename().string() + " visit " + std::to_string(visit);
  std::string reader;
  {
    storage::ProjectStore store = storage::ProjectStore::open(file);
    const std::string text =
        storage::make_scene_json(storage::load_scene_source(store, visit)).dump();
    reader = test::refusal([&] { storage::parse_scene(text, name); });
  }
  EXPECT_EQ(reader, name + ": traces[8].joint: unknown joint id \"J404\"");
  NoProgress progress;
  app::StoreTraceMapRunner runner;
  EXPECT_EQ(test::refusal([&] { runner.update(file, visit, progress); }), reader);
}

// The screen: opening Mapping shows the demo visit's blocks; a trace tapped
// and saved updates them in the same task.
TEST(MapBlocks, TheMappingScreenShowsTheBlocksAndUpdatesThemAfterASavedTrace) {
  const fs::path file = test_dir() / "demo.rockface";
  fs::copy_file(test::demo_project(), file, fs::copy_options::overwrite_existing);
  app::StoreTraceMapRunner runner;
  ui::FieldServices services;
  services.trace_map = &runner;
  ui::UiOptions options;
  options.project = file;
  options.scale = 0.6f;
  options.max_display_triangles = 20000;
  ui::HeadlessSession s(options, services, 800, 500);
  s.settle();
  s.tap("Mapping");
  s.settle();
  const ui::MapBlocksState& blocks = s.state().mapping.blocks;
  ASSERT_TRUE(blocks.verdicts) << blocks.problem;
  const int before = blocks.verdicts->traces;
  EXPECT_GT(before, 0);
  const ui::ModelView& view = s.state().model_view;
  const auto centre = view.to_screen(view.display_mesh().centre);
  ASSERT_TRUE(centre);
  for (int i = 0; i < 4; ++i) s.tap(centre->x - 60 + 40 * i, centre->y - 30 + 20 * i);
  ASSERT_EQ(s.state().mapping.marker.taps().size(), 4u) << s.state().mapping.marker.problem();
  s.tap("Save trace");
  s.settle();
  ASSERT_TRUE(blocks.verdicts) << blocks.problem;
  EXPECT_EQ(blocks.verdicts->traces, before + 1);
  // Said on the Mapping screen's own status line.
  const std::string said = s.state().statuses.line(static_cast<std::size_t>(ui::Screen::mapping));
  EXPECT_NE(said.find("updated in"), std::string::npos) << said;
  const storage::RecordId visit = *s.state().session->visit();
  expect_same_as_full_analysis(file, visit, *blocks.verdicts);
}

}  // namespace
