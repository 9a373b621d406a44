// `rockface replay` end to end: the mock camera renders and captures the
// demo tunnel face, the pair is reconstructed and registered, the true traces
// are analysed, and every step lands in the project file. Twice: a second
// visit, not a duplicate.
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/test_paths.h"

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args, const fs::path& log) {
  const std::string cmd =
      std::string(ROCKFACE_BINARY_DIR) + "/rockface " + args + " >" + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Replay, TwoRunsGiveTwoVisitsWithEverythingStored) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-replay-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path project = dir / "site.rockface";
  const std::string scene =
      std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json";
  ASSERT_EQ(run("replay " + scene + " --project " + project.string(), dir / "run1.txt"), 0);
  ASSERT_EQ(run("replay " + scene + " --project " + project.string(), dir / "run2.txt"), 0);

  auto store = rockface::storage::ProjectStore::open(project);
  EXPECT_FALSE(store.read_only());
  EXPECT_TRUE(store.check_integrity().ok);
  const auto visits = store.list_visits();
  ASSERT_EQ(visits.size(), 2u);
  for (const auto& v : visits) {
    const auto captures = store.list_captures(v.id);
    ASSERT_EQ(captures.size(), 1u) << "visit " << v.id;
    EXPECT_FALSE(store.load_capture_image(captures[0].id, "left").bytes.empty());
    const auto models = store.list_models(captures[0].id);
    ASSERT_EQ(models.size(), 1u);
    EXPECT_GT(models[0].vertex_count, 10000);  // a dense surface, not a sparse cloud
    EXPECT_EQ(models[0].registration_kind, "range_pole_compass");
    EXPECT_FALSE(store.list_measurements(v.id).empty());  // the traces
    EXPECT_EQ(store.list_joints(v.id).size(), 3u);
    const auto runs = store.list_analyses(v.id);
    ASSERT_EQ(runs.size(), 1u);
    const auto run = store.load_analysis(runs[0].id);
    EXPECT_FALSE(run.blocks.empty());
    // The demo's three joints meet 0.8 m behind the face: one keyblock on
    // the face, finite and removable, with its geometry; every other closed
    // loop widens into the rock.
    int finite = 0;
    for (const auto& b : run.blocks) {
      EXPECT_EQ(b.source, "traces");
      ASSERT_FALSE(b.report_json.empty());
      const auto j = nlohmann::json::parse(b.report_json);
      if (!j.value("finite", false)) continue;
      ++finite;
      EXPECT_TRUE(j.value("removable", false));
      // The true block is 0.77 m^3 (tests/core/faces/tunnel_face_keyblock_test):
      // the traces here are the exact ones, so only a volume is asserted.
      EXPECT_GT(j.value("volume", 0.0), 0.5);
    }
    EXPECT_EQ(finite, 1);
  }
  fs::remove_all(dir);
}

TEST(Replay, BadSourceIsBadInputAndCreatesNoProject) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-replay-bad-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path project = dir / "none.rockface";
  EXPECT_EQ(run("replay /nonexistent/scene.json --project " + project.string(), dir / "log.txt"),
            2);
  EXPECT_FALSE(fs::exists(project));
  fs::remove_all(dir);
}

}  // namespace
