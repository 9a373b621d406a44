#pragma once
// The demo project of the UI suites: `rockface replay` of the demo tunnel
// face (fast preset), made once per test binary; tests that write get a copy.
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/test_paths.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

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

// The demo face photographed as two stereo pairs (the second 1.2 m west of
// the first, as in replay_face_picks_test.cpp), replayed at the fast
// preset: a visit with two 3D images in one face frame. Made once per test
// binary, only by the tests that ask for it.
inline const std::filesystem::path& two_pair_project() {
  static const std::filesystem::path project = [] {
    std::ifstream in(demo_scene());
    nlohmann::json scene = nlohmann::json::parse(in);
    const nlohmann::json first = scene["imaging"]["stations"];
    for (auto st : first) {
      st["position"][0] = st["position"][0].get<double>() - 1.2;
      st["look_at"][0] = st["look_at"][0].get<double>() - 1.2;
      scene["imaging"]["stations"].push_back(st);
    }
    const auto file = ui_test_dir() / "two-pairs.scene.json";
    std::ofstream(file) << scene.dump(2);
    const auto p = ui_test_dir() / "two-pairs.rockface";
    if (run_rockface_logged("replay " + file.string() + " --preset fast --project " + p.string(),
                            ui_test_dir() / "replay-two-pairs.txt") != 0)
      throw std::runtime_error("rockface replay of the two-pair demo failed: see " +
                               (ui_test_dir() / "replay-two-pairs.txt").string());
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
