#pragma once
// The demo project of the UI suites: `rockface replay` of the demo tunnel
// face (fast preset), made once per test binary; tests that write get a copy.
// The binary's folder goes when its tests pass (tests/support/temp_folders.h).
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/demo_projects.h"
#include "tests/support/temp_folders.h"
#include "tests/support/test_paths.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

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

// The demo scene's file (the UI suites' name for it).
inline std::string demo_scene() {
  return demo_scene_file();
}

// The demo project `name` in this process's folder, made once per process.
// Under CTest it is a copy of the replay the ui_demo_projects fixture made
// for every UI suite (the same `rockface replay` of the same scene: a
// replay is ~8 s of CPU, and each suite's process, each test of the
// session suite, made its own); run by hand, the process replays it.
inline std::filesystem::path demo_project_named(const std::string& name) {
  const auto project = ui_test_dir() / (name + ".rockface");
  copy_of_shared_demo_project(name, project);
  return project;
}

inline const std::filesystem::path& demo_project() {
  static const std::filesystem::path project = demo_project_named("demo");
  return project;
}

// The demo face photographed as two and as three pairs, replayed at the
// fast preset: a visit with several 3D images in one face frame. Made once
// per test binary and pair count, only by the tests that ask.
inline const std::filesystem::path& two_pair_project() {
  static const std::filesystem::path project = demo_project_named("two-pairs");
  return project;
}

inline const std::filesystem::path& three_pair_project() {
  static const std::filesystem::path project = demo_project_named("three-pairs");
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
