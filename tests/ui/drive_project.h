#pragma once
// The tunnel-drive sample's project for the tablet's tunnel suites (issue
// 39): `rockface replay` of tools/samples/tunnel-drive.scene.json (a visit
// placed in the drive, three joints, one trace or more each, no joint sets),
// made once per test binary; tests that write get a copy. The binary's
// folder goes when its tests pass.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/ui/demo_project.h"

namespace rockface::test {

inline std::filesystem::path drive_scene() {
  return std::filesystem::path(ROCKFACE_SOURCE_DIR) / "tools/samples/tunnel-drive.scene.json";
}

inline nlohmann::json drive_scene_json() {
  std::ifstream in(drive_scene());
  return nlohmann::json::parse(in);
}

inline const std::filesystem::path& drive_project() {
  static const std::filesystem::path project = [] {
    const auto p = ui_test_dir() / "drive.rockface";
    if (run_rockface_logged("replay " + drive_scene().string() + " --project " + p.string(),
                            ui_test_dir() / "replay-drive.txt") != 0)
      throw std::runtime_error("rockface replay of the tunnel drive failed: see " +
                               (ui_test_dir() / "replay-drive.txt").string());
    return p;
  }();
  return project;
}

// A copy of the drive project for a test that writes to it.
inline std::filesystem::path drive_project_copy(const std::string& name) {
  const auto to = ui_test_dir() / (name + ".rockface");
  std::filesystem::copy_file(drive_project(), to,
                             std::filesystem::copy_options::overwrite_existing);
  return to;
}

}  // namespace rockface::test
