// Issue 41: a replay refused for a bad placement (a chainage of 1e308, off
// the alignment) left a new project behind, with a visit, its capture and
// its model, and a spool folder of shots. A replay refused before its first
// visit is stored leaves no new project, and an existing one unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The sample tunnel scene beside its alignment and profile, its typed
// placement at `chainage`.
fs::path scene_placed_at(const fs::path& dir, double chainage) {
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools" / "samples";
  for (const char* f : {"tunnel-drive.alignment.csv", "tunnel-drive.profile.json"})
    fs::copy_file(samples / f, dir / f, fs::copy_options::overwrite_existing);
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(samples / "tunnel-drive.scene.json"));
  scene["tunnel"]["placement"]["chainage"] = chainage;
  const fs::path out = dir / "placed.scene.json";
  std::ofstream(out) << scene.dump(1);
  return out;
}

}  // namespace

TEST(ReplayRefusedCli, APlacementOffTheAlignmentLeavesNoProject) {
  const fs::path dir = fs::temp_directory_path() / "replay-refused-cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = scene_placed_at(dir, 1e308);
  const fs::path p = dir / "p.rockface";
  const auto r = rockface::test::run_rockface("replay " + scene.string() + " --project " +
                                              p.string() + " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("tunnel.placement.chainage"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("off the alignment"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(p));
  EXPECT_FALSE(fs::exists(dir / "p.rockface.spool"));
  EXPECT_FALSE(fs::exists(dir / "p.rockface-wal"));
  fs::remove_all(dir);
}

TEST(ReplayRefusedCli, AnExistingProjectIsLeftAsItWas) {
  const fs::path dir = fs::temp_directory_path() / "replay-refused-cli-existing";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = scene_placed_at(dir, -1e308);
  const fs::path p = dir / "p.rockface";
  {
    rockface::storage::ProjectInfo info;
    info.name = "replayed before";
    auto store = rockface::storage::ProjectStore::create(p, info);
    store.begin_visit("test");
  }
  const std::string bytes = bytes_of(p);
  const auto r = rockface::test::run_rockface("replay " + scene.string() + " --project " +
                                              p.string() + " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("tunnel.placement.chainage"), std::string::npos) << r.err;
  EXPECT_TRUE(bytes_of(p) == bytes) << "the project changed";
  EXPECT_FALSE(fs::exists(dir / "p.rockface.spool"));
  EXPECT_FALSE(fs::exists(dir / "p.rockface-wal"));
  EXPECT_EQ(rockface::storage::ProjectStore::open(p).list_visits().size(), 1u);
  fs::remove_all(dir);
}
