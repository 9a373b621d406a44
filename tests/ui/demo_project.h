#pragma once
// The demo project of the UI suites: `rockface replay` of the demo tunnel
// face (fast preset), made once per test binary; tests that write get a copy.
// The binary's folder goes when its tests pass (tests/support/temp_folders.h).
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/temp_folders.h"
#include "tests/support/test_paths.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
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
    remove_when_passed(d);
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

// The demo face photographed as `pairs` stereo pairs (each further pair
// `step_m` west of the one before; 1.2 m as in replay_face_picks_test.cpp
// for two; closer for three, whose third pair must still see the lit face
// and the pole), replayed
// at the fast preset: a visit with several 3D images in one face frame.
// Made once per test binary and pair count, only by the tests that ask.
inline std::filesystem::path replay_of_pairs(int pairs, double step_m, const std::string& name) {
  std::ifstream in(demo_scene());
  nlohmann::json scene = nlohmann::json::parse(in);
  const nlohmann::json first = scene["imaging"]["stations"];
  for (int k = 1; k < pairs; ++k)
    for (auto st : first) {
      st["position"][0] = st["position"][0].get<double>() - step_m * k;
      st["look_at"][0] = st["look_at"][0].get<double>() - step_m * k;
      scene["imaging"]["stations"].push_back(st);
    }
  const auto file = ui_test_dir() / (name + ".scene.json");
  std::ofstream(file) << scene.dump(2);
  const auto p = ui_test_dir() / (name + ".rockface");
  if (run_rockface_logged("replay " + file.string() + " --preset fast --project " + p.string(),
                          ui_test_dir() / ("replay-" + name + ".txt")) != 0)
    throw std::runtime_error("rockface replay of the " + name + " demo failed: see " +
                             (ui_test_dir() / ("replay-" + name + ".txt")).string());
  return p;
}

inline const std::filesystem::path& two_pair_project() {
  static const std::filesystem::path project = replay_of_pairs(2, 1.2, "two-pairs");
  return project;
}

inline const std::filesystem::path& three_pair_project() {
  static const std::filesystem::path project = replay_of_pairs(3, 0.7, "three-pairs");
  return project;
}

inline std::filesystem::path copy_of_demo(const std::string& name) {
  const auto to = ui_test_dir() / (name + ".rockface");
  std::filesystem::copy_file(demo_project(), to, std::filesystem::copy_options::overwrite_existing);
  return to;
}

// The whole text of a file.
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p);
  return {std::istreambuf_iterator<char>(f), {}};
}

// `rockface ui --headless --script` on `project` with the demo scene's mock
// camera, a small viewport and a decimated model (CI's budget): the steps
// (a JSON array) go to NAME.json, screenshots to NAME/, the log to NAME.txt
// in ui_test_dir(). Returns the exit code.
inline int run_demo_script(const std::filesystem::path& project, const std::string& steps,
                           const std::string& name) {
  const std::filesystem::path script = ui_test_dir() / (name + ".json");
  std::ofstream(script) << R"({"viewport": [800, 500], "steps": )" << steps << "}";
  return run_rockface_logged("ui --project " + project.string() + " --camera " + demo_scene() +
                                 " --scale 0.6 --max-triangles 20000 --headless --script " +
                                 script.string() + " --screenshots " +
                                 (ui_test_dir() / name).string(),
                             ui_test_dir() / (name + ".txt"));
}

}  // namespace rockface::test
