#pragma once
// The demo face replayed at the fast preset as the suites open it: `rockface
// replay` of tools/samples/tunnel-face-demo.scene.json as one, two and three
// pairs, and without its picks. CTest's ui_demo_projects fixture
// (tests/ui/demo_projects_main.cpp) replays them once per run into the
// folder ROCKFACE_TEST_DEMO_PROJECTS names; a process copies them from there
// (copy_of_shared_demo_project), or, run by hand, replays its own.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/test_paths.h"

namespace rockface::test {

// `prefix` goes before the binary (e.g. "env -u DISPLAY ").
inline int run_rockface_logged(const std::string& args, const std::filesystem::path& log,
                               const std::string& prefix = "") {
  const std::string cmd = prefix + std::string(ROCKFACE_BINARY_DIR) + "/rockface " + args + " >" +
                          log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string demo_scene_file() {
  return std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json";
}

// The variable CTest sets to the folder where its ui_demo_projects fixture
// (tests/ui/demo_projects_main.cpp) replayed the demo projects once for all
// the UI suites' processes (tests/ui/CMakeLists.txt).
inline constexpr const char* kSharedDemoProjects = "ROCKFACE_TEST_DEMO_PROJECTS";

// `rockface replay` of `scene` at the fast preset into `project` (a new
// file), its output in `log`.
inline void replay_demo_scene(const std::filesystem::path& scene,
                              const std::filesystem::path& project,
                              const std::filesystem::path& log) {
  std::filesystem::remove(project);
  if (run_rockface_logged(
          "replay " + scene.string() + " --preset fast --project " + project.string(), log) != 0)
    throw std::runtime_error("rockface replay of " + scene.filename().string() + " failed: see " +
                             log.string());
}

// The demo scene with the face photographed as `pairs` stereo pairs (each
// further pair `step_m` west of the one before; 1.2 m as in
// replay_face_picks_test.cpp for two; closer for three, whose third pair
// must still see the lit face and the pole), written to `file`.
inline void write_pairs_scene(int pairs, double step_m, const std::filesystem::path& file) {
  std::ifstream in(demo_scene_file());
  nlohmann::json scene = nlohmann::json::parse(in);
  const nlohmann::json first = scene["imaging"]["stations"];
  for (int k = 1; k < pairs; ++k)
    for (auto st : first) {
      st["position"][0] = st["position"][0].get<double>() - step_m * k;
      st["look_at"][0] = st["look_at"][0].get<double>() - step_m * k;
      scene["imaging"]["stations"].push_back(st);
    }
  std::ofstream(file) << scene.dump(2);
}

// The demo projects the UI suites open: the demo face (one pair) and the
// visits of two and three pairs. Each is made by `make` (writing the scene
// file it replays into the folder it is given), and named `name`.rockface.
// "bare" is the demo face without its picks (no traces, joints or blocks
// yet): what the command-line suites measure and propose on.
struct DemoProjectRecipe {
  std::string name;
  int pairs;
  double step_m;
  bool without_picks = false;
};
inline const std::vector<DemoProjectRecipe>& demo_project_recipes() {
  static const std::vector<DemoProjectRecipe> recipes = {
      {"demo", 1, 0.0}, {"two-pairs", 2, 1.2}, {"three-pairs", 3, 0.7}, {"bare", 1, 0.0, true}};
  return recipes;
}

// Replays recipe `r` into `dir` (its scene file and log beside it).
inline std::filesystem::path make_demo_project(const DemoProjectRecipe& r,
                                               const std::filesystem::path& dir) {
  std::filesystem::path scene = demo_scene_file();
  if (r.pairs > 1) {
    scene = dir / (r.name + ".scene.json");
    write_pairs_scene(r.pairs, r.step_m, scene);
  } else if (r.without_picks) {
    std::ifstream in(demo_scene_file());
    nlohmann::json bare = nlohmann::json::parse(in);
    bare.erase("picks");
    scene = dir / (r.name + ".scene.json");
    std::ofstream(scene) << bare.dump(2);
  }
  const auto project = dir / (r.name + ".rockface");
  replay_demo_scene(scene, project, dir / ("replay-" + r.name + ".txt"));
  return project;
}

// The shared demo project `name` copied to `to` (a new file): under CTest
// the fixture's replay, else replayed here (its scene and log beside `to`).
inline void copy_of_shared_demo_project(const std::string& name, const std::filesystem::path& to) {
  std::filesystem::path made;
  if (const char* shared = std::getenv(kSharedDemoProjects); shared && *shared) {
    made = std::filesystem::path(shared) / (name + ".rockface");
    if (!std::filesystem::exists(made))
      throw std::runtime_error(made.string() + " is missing: the ui_demo_projects fixture (" +
                               std::string(kSharedDemoProjects) + ") did not make it");
  } else {
    for (const DemoProjectRecipe& r : demo_project_recipes())
      if (r.name == name) made = make_demo_project(r, to.parent_path());
    if (made.empty()) throw std::logic_error("no demo project " + name);
    if (made == to) return;
  }
  std::filesystem::copy_file(made, to, std::filesystem::copy_options::overwrite_existing);
}

}  // namespace rockface::test
