// Issue 41: `profile`, `drive` and `wedges` refused on a project without a
// tunnel left `-wal` / `-shm` files beside it. A refusal leaves the
// project's folder as it was and the project's bytes unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A project with one visit and no tunnel, alone in its folder.
fs::path project_without_tunnel(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("refused-read-cli-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  rockface::storage::ProjectInfo info;
  info.name = "no tunnel";
  info.datum = {2690123.25, 1170456.5, 1105.125};
  const fs::path file = dir / "p.rockface";
  auto store = rockface::storage::ProjectStore::create(file, info);
  store.begin_visit("test");
  return file;
}

void expect_refused_leaving_nothing(const std::string& verb, const std::string& args) {
  const fs::path p = project_without_tunnel(verb);
  const auto before = listing(p.parent_path());
  ASSERT_EQ(before, std::set<std::string>{"p.rockface"});
  const std::string bytes = bytes_of(p);
  const auto r = rockface::test::run_rockface(verb + " " + p.string() + " " + args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("tunnel"), std::string::npos) << r.err;
  EXPECT_EQ(listing(p.parent_path()), before) << verb;
  EXPECT_TRUE(bytes_of(p) == bytes) << "the project changed: " << verb;
  fs::remove_all(p.parent_path());
}

}  // namespace

TEST(RefusedReadCli, ProfileLeavesNothing) {
  expect_refused_leaving_nothing("profile", "--out /tmp/refused-read-cli-profile-dev.png");
  EXPECT_FALSE(fs::exists("/tmp/refused-read-cli-profile-dev.png"));
}

TEST(RefusedReadCli, DriveLeavesNothing) {
  expect_refused_leaving_nothing("drive", "--out /tmp/refused-read-cli-drive.png");
  EXPECT_FALSE(fs::exists("/tmp/refused-read-cli-drive.png"));
}

TEST(RefusedReadCli, WedgesLeavesNothing) {
  expect_refused_leaving_nothing("wedges", "--out /tmp/refused-read-cli-wedges.json");
  EXPECT_FALSE(fs::exists("/tmp/refused-read-cli-wedges.json"));
}
