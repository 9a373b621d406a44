#pragma once
// Shared by the command-line suites: runs the real rockface binary with arguments, capturing exit
// code, stdout and stderr.
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/temp_folders.h"
#include "tests/support/test_paths.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rockface::test {

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

inline CliRun run_rockface(const std::string& args) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rockface-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  remove_when_passed(dir);
  const std::string out = (dir / "out.txt").string(), err = (dir / "err.txt").string();
  const std::string cmd =
      std::string(ROCKFACE_BINARY_DIR) + "/rockface " + args + " >" + out + " 2>" + err;
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
  };
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// Any other program the tests run (an independent reader: python3-ezdxf,
// CloudCompare): its exit code and what it printed, stderr with stdout in `out`.
inline CliRun run_command(const std::string& command) {
  CliRun r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) r.out += buffer;
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace rockface::test
