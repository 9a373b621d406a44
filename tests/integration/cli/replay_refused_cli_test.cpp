// Issue 41: a replay refused for a bad placement (a chainage of 1e308, off
// the alignment) left a new project behind, with a visit, its capture and
// its model, and a spool folder of shots. A replay refused before its first
// visit is stored leaves no new project, and an existing one unchanged; so
// does a replay refused after its visit began (its face off the alignment:
// it left a new project with a half-stored visit, and a visit in an
// existing one).
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

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
// placement at `chainage`, as NAME.scene.json.
fs::path scene_placed_at(const fs::path& dir, double chainage, const std::string& name = "placed") {
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools" / "samples";
  for (const char* f : {"tunnel-drive.alignment.csv", "tunnel-drive.profile.json"})
    fs::copy_file(samples / f, dir / f, fs::copy_options::overwrite_existing);
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(samples / "tunnel-drive.scene.json"));
  scene["tunnel"]["placement"]["chainage"] = chainage;
  const fs::path out = dir / (name + ".scene.json");
  std::ofstream(out) << scene.dump(1);
  return out;
}

// A project a replay comes to with a visit of its own already.
void project_with_a_visit(const fs::path& p) {
  rockface::storage::ProjectInfo info;
  info.name = "replayed before";
  auto store = rockface::storage::ProjectStore::create(p, info);
  store.begin_visit("test");
}

}  // namespace

TEST(ReplayRefusedCli, APlacementOffTheAlignmentLeavesNoProject) {
  const fs::path dir =
      fs::temp_directory_path() / ("replay-refused-cli-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = scene_placed_at(dir, 1e308);
  const fs::path p = dir / "p.rockface";
  const auto r = rockface::test::run_rockface("replay " + scene.string() + " --project " +
                                              p.string() + " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  // The scene file and its field, as every refusal of a scene's value says
  // them (it said only the field).
  EXPECT_NE(r.err.find(scene.string() + ": tunnel.placement.chainage"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("off the alignment"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(p));
  EXPECT_FALSE(fs::exists(dir / "p.rockface.spool"));
  EXPECT_FALSE(fs::exists(dir / "p.rockface-wal"));
  fs::remove_all(dir);
}

TEST(ReplayRefusedCli, AnExistingProjectIsLeftAsItWas) {
  const fs::path dir =
      fs::temp_directory_path() / ("replay-refused-cli-existing-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = scene_placed_at(dir, -1e308);
  const fs::path p = dir / "p.rockface";
  project_with_a_visit(p);
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

// The pole typed 0.5 m before the end of the 200 m alignment: the face it
// photographs lies 1.1 m ahead, past the end. The replay captures,
// reconstructs and begins the visit before placing it; the placement is
// refused then.
constexpr double kPoleBeforeTheEnd = 199.5;

TEST(ReplayRefusedCli, AFaceOffTheAlignmentFoundAfterTheVisitBeganLeavesNoProject) {
  const fs::path dir =
      fs::temp_directory_path() / ("replay-refused-cli-face-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = scene_placed_at(dir, kPoleBeforeTheEnd);
  const fs::path p = dir / "p.rockface";
  const auto r = rockface::test::run_rockface("replay " + scene.string() + " --project " +
                                              p.string() + " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("its face lies at chainage"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; the replay stored nothing: no project was made\n"), std::string::npos)
      << r.err;
  for (const char* left :
       {"p.rockface", "p.rockface.spool", "p.rockface-wal", "p.rockface-shm", "p.rockface-journal"})
    EXPECT_FALSE(fs::exists(dir / left)) << left << " left behind";
  fs::remove_all(dir);
}

TEST(ReplayRefusedCli, AFaceOffTheAlignmentChangesNothingInAProjectWithVisits) {
  const fs::path dir = fs::temp_directory_path() /
                       ("replay-refused-cli-face-existing-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path good = scene_placed_at(dir, 110.6, "good");  // the sample's own placement
  const fs::path bad = scene_placed_at(dir, kPoleBeforeTheEnd, "bad");
  const fs::path p = dir / "p.rockface";
  const auto first = rockface::test::run_rockface("replay " + good.string() + " --project " +
                                                  p.string() + " --preset fast");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::string bytes = bytes_of(p);
  std::vector<fs::path> spooled;
  for (const auto& e : fs::recursive_directory_iterator(dir / "p.rockface.spool"))
    spooled.push_back(e.path());
  ASSERT_FALSE(spooled.empty());
  const auto r = rockface::test::run_rockface("replay " + bad.string() + " --project " +
                                              p.string() + " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("its face lies at chainage"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; the replay stored nothing: the project is as it was\n"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(bytes_of(p) == bytes) << "the project changed";
  for (const char* left : {"p.rockface-wal", "p.rockface-shm", "p.rockface-journal"})
    EXPECT_FALSE(fs::exists(dir / left)) << left << " left behind";
  std::vector<fs::path> after;
  for (const auto& e : fs::recursive_directory_iterator(dir / "p.rockface.spool"))
    after.push_back(e.path());
  std::sort(spooled.begin(), spooled.end());
  std::sort(after.begin(), after.end());
  EXPECT_EQ(after, spooled) << "the spool holds shots of the refused replay";
  auto store = rockface::storage::ProjectStore::open(p);
  EXPECT_EQ(store.list_visits().size(), 1u);
  fs::remove_all(dir);
}

TEST(ReplayRefusedCli, AnAlignmentBeyondSurveyCoordinatesChangesNothing) {
  const fs::path dir =
      fs::temp_directory_path() / ("replay-refused-cli-alignment-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = scene_placed_at(dir, 110.6);
  std::ofstream(dir / "tunnel-drive.alignment.csv")
      << "chainage,easting,northing,elevation,radius\n"
         "0,512340,5211800,410,0\n100,1e308,5211900,410,0\n200,512340,5212000,410,\n";
  const fs::path p = dir / "p.rockface";
  project_with_a_visit(p);
  const std::string bytes = bytes_of(p);
  const auto r = rockface::test::run_rockface("replay " + scene.string() + " --project " +
                                              p.string() + " --preset fast");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("tunnel-drive.alignment.csv:3"), std::string::npos) << r.err;
  EXPECT_TRUE(bytes_of(p) == bytes) << "the project changed";
  for (const char* left : {"p.rockface.spool", "p.rockface-wal", "p.rockface-shm"})
    EXPECT_FALSE(fs::exists(dir / left)) << left << " left behind";
  fs::remove(p);
  const auto fresh = rockface::test::run_rockface("replay " + scene.string() + " --project " +
                                                  p.string() + " --preset fast");
  EXPECT_EQ(fresh.exit_code, 2) << fresh.err;
  EXPECT_FALSE(fs::exists(p));
  fs::remove_all(dir);
}
