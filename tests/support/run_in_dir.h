#pragma once
// The command-line suites that keep each test's files in a folder of their
// own: the folder made fresh, the rockface binary run with its output in
// that folder (out.txt, err.txt), a file of it read back whole.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/temp_folders.h"
#include "tests/support/test_paths.h"

namespace rockface::test {

// A fresh folder /tmp/NAME-PID for one test's files, removed when the
// binary's tests pass.
inline std::filesystem::path fresh_test_dir(const std::string& name) {
  const std::filesystem::path d =
      std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  remove_when_passed(d);
  return d;
}

// Runs the rockface binary with `args`, its stdout and stderr written to
// DIR/out.txt and DIR/err.txt (read with read_text); returns its exit code.
inline int run_rockface_in(const std::string& args, const std::filesystem::path& dir) {
  const std::string cmd = std::string(ROCKFACE_BINARY_DIR) + "/rockface " + args + " > " +
                          (dir / "out.txt").string() + " 2> " + (dir / "err.txt").string();
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A file's whole text (empty if it cannot be read).
inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace rockface::test
