#pragma once
// The demo project of the UI suites: `rockface replay` of the demo tunnel
// face (fast preset), made once per test binary; tests that write get a copy.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace rockface::test {

inline std::filesystem::path ui_test_dir() {
  static const std::filesystem::path dir = [] {
    const auto d =
        std::filesystem::temp_directory_path() / ("rockface-ui-" + std::to_string(::getpid()));
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

// `prefix` goes before the binary (e.g. "env -u DISPLAY ").
inline int run_rockface_logged(const std::string& args, const std::filesystem::path& log,
                               const std::string& prefix = "") {
  const std::string cmd = prefix + std::string(ROCKFACE_BINARY_DIR) + "/rockface " + args + " >" +
                          log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string demo_scene() {
  return std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json";
}

inline const std::filesystem::path& demo_project() {
  static const std::filesystem::path project = [] {
    const auto p = ui_test_dir() / "demo.rockface";
    if (run_rockface_logged("replay " + demo_scene() + " --preset fast --project " + p.string(),
                            ui_test_dir() / "replay.txt") != 0)
      throw std::runtime_error("rockface replay of the demo failed: see " +
                               (ui_test_dir() / "replay.txt").string());
    return p;
  }();
  return project;
}

inline std::filesystem::path copy_of_demo(const std::string& name) {
  const auto to = ui_test_dir() / (name + ".rockface");
  std::filesystem::copy_file(demo_project(), to, std::filesystem::copy_options::overwrite_existing);
  return to;
}

}  // namespace rockface::test
