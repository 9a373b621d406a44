// Issue 41: a number beyond double's range in a file a scene names (here the
// tunnel's design profile) is bad input: exit 2 and one line naming the file
// and where, not nlohmann's bare "[json.exception.out_of_range.406]" (exit 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(HostileJsonCli, ProfileNumberOverflowIsExit2NamingFileAndPosition) {
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
  const fs::path dir = fs::temp_directory_path() / "hostile-json-cli-profile";
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(samples / "tunnel-drive.scene.json", dir / "tunnel-drive.scene.json");
  fs::copy_file(samples / "tunnel-drive.alignment.csv", dir / "tunnel-drive.alignment.csv");
  std::string profile = read(samples / "tunnel-drive.profile.json");
  const auto at = profile.find("2.330127");
  ASSERT_NE(at, std::string::npos);
  profile.replace(at, 8, "1e309");
  std::ofstream(dir / "tunnel-drive.profile.json") << profile;

  const auto r =
      rockface::test::run_rockface("analyse " + (dir / "tunnel-drive.scene.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("tunnel-drive.profile.json: segments[0].line.to[0]: 1e309"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1e309 is beyond the range of a number"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

// Found while issue 41's replays were re-run: a scene named by a path
// longer than the file system takes (a name of 300 characters) exited 1
// with std::filesystem's "filesystem error: status: File name too long".
// The path is the user's input: exit 2 naming it.
TEST(HostileJsonCli, APathTooLongForTheFileSystemIsBadInput) {
  const std::string name = "/tmp/" + std::string(300, 'x') + ".scene.json";
  const auto r =
      rockface::test::run_rockface("replay " + name + " --project /tmp/too-long.rockface");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "rockface: " + name + ": the name is too long for the file system\n");
  EXPECT_FALSE(fs::exists("/tmp/too-long.rockface"));
  // analyse opens the file without asking the file system first: it could
  // not open it, and says so by name.
  const auto a = rockface::test::run_rockface("analyse " + name);
  EXPECT_EQ(a.exit_code, 2) << a.err;
  EXPECT_NE(a.err.find(name), std::string::npos) << a.err;
}
