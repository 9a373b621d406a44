// The office server as a systemd service (issue 46): tools/rockface-office.service
// checked by systemd's own verifier (Debian's systemd, `systemd-analyze
// verify`) with its ExecStart pointed at this build's rockface, and its
// command line read back against the binary: `rockface office serve` with
// only options the verb has, its work folder the unit's runtime folder,
// and the README naming the file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace rockface::office_web_test {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The value of `key=` in the unit's [Service] section ("" when absent).
std::string service_value(const std::string& unit, const std::string& key) {
  std::istringstream in(unit);
  std::string line, section;
  while (std::getline(in, line)) {
    if (!line.empty() && line.front() == '[') section = line;
    if (section == "[Service]" && line.rfind(key + "=", 0) == 0) return line.substr(key.size() + 1);
  }
  return "";
}

// A command line split as systemd splits ExecStart: on spaces, a "quoted"
// word kept whole.
std::vector<std::string> words(const std::string& command) {
  std::vector<std::string> out;
  std::string word;
  bool quoted = false, any = false;
  for (char c : command) {
    if (c == '"') {
      quoted = !quoted;
      any = true;
    } else if (c == ' ' && !quoted) {
      if (any) out.push_back(word);
      word.clear();
      any = false;
    } else {
      word += c;
      any = true;
    }
  }
  if (any) out.push_back(word);
  return out;
}

TEST(OfficeServiceUnit, SystemdVerifiesTheUnitAndItRunsOfficeServeWithTheVerbsOptions) {
  const fs::path unit_file = fs::path(ROCKFACE_SOURCE_DIR) / "tools/rockface-office.service";
  ASSERT_TRUE(fs::exists(unit_file)) << unit_file;
  const std::string unit = slurp(unit_file);

  const std::string exec = service_value(unit, "ExecStart");
  const std::vector<std::string> command = words(exec);
  ASSERT_GE(command.size(), 4u) << "ExecStart=" << exec;
  EXPECT_EQ(fs::path(command[0]).filename(), "rockface") << exec;
  EXPECT_TRUE(fs::path(command[0]).is_absolute()) << "systemd needs the binary's full path";
  EXPECT_EQ(command[1], "office") << exec;
  EXPECT_EQ(command[2], "serve") << exec;
  EXPECT_EQ(command[3].rfind("postgresql://", 0), 0u) << "the office database first: " << exec;
  // Every option of the command line is one the verb has.
  const test::CliRun help = test::run_rockface("office serve --help");
  ASSERT_EQ(help.exit_code, 0) << help.err;
  std::string work;
  for (std::size_t i = 4; i < command.size(); ++i) {
    if (command[i].rfind("--", 0) != 0) continue;
    EXPECT_NE(help.out.find(command[i]), std::string::npos)
        << "ExecStart gives " << command[i] << ", which `rockface office serve` does not have";
    if (command[i] == "--work" && i + 1 < command.size()) work = command[i + 1];
  }
  // The pulled copies go in the folder systemd makes for the service
  // (RuntimeDirectory=NAME is /run/NAME) and removes when it stops.
  const std::string runtime = service_value(unit, "RuntimeDirectory");
  ASSERT_FALSE(runtime.empty()) << "no RuntimeDirectory for the pulled copies";
  EXPECT_EQ(work, "/run/" + runtime);
  EXPECT_EQ(service_value(unit, "KillSignal"), "SIGTERM") << "the server stops cleanly on SIGTERM";
  // The README tells where the unit is.
  EXPECT_NE(
      slurp(fs::path(ROCKFACE_SOURCE_DIR) / "README.md").find("tools/rockface-office.service"),
      std::string::npos);

  // systemd's own check of the unit, its binary this build's (the unit's
  // path is where a site installs it).
  const char* verifier = "/usr/bin/systemd-analyze";
  if (!fs::exists(verifier)) GTEST_SKIP() << "systemd-analyze (Debian's systemd) is not installed";
  const fs::path dir =
      fs::temp_directory_path() /
      ("rockface-office-unit-" + std::to_string(::getpid()) + "-" +
       std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  fs::create_directories(dir);
  const fs::path copy = dir / "rockface-office.service";
  {
    std::string here = unit;
    here.replace(here.find(command[0]), command[0].size(),
                 (fs::path(ROCKFACE_BINARY_DIR) / "rockface").string());
    std::ofstream(copy) << here;
  }
  const fs::path said = dir / "verify.txt";
  const int status = std::system(
      (std::string(verifier) + " verify " + copy.string() + " >" + said.string() + " 2>&1")
          .c_str());
  const std::string verdict = slurp(said);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0) << verdict;
  // Anything it says of the unit is a fault of the unit (its warnings too).
  EXPECT_EQ(verdict.find("rockface-office.service"), std::string::npos) << verdict;
  std::error_code ec;
  if (!::testing::Test::HasFailure()) fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace rockface::office_web_test
