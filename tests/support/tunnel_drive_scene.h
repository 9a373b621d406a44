#pragma once
// The sample heading's scene (tools/samples/tunnel-drive.scene.json) as the
// tunnel suites start from it: its alignment and design profile by absolute
// path, so that a copy written anywhere still finds them; and the quick
// camera several of them replay it with.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/support/test_paths.h"

namespace rockface::test {

inline nlohmann::json tunnel_drive_scene() {
  const std::filesystem::path samples =
      std::filesystem::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
  std::ifstream in(samples / "tunnel-drive.scene.json");
  nlohmann::json s = nlohmann::json::parse(in);
  s["tunnel"]["alignment"] = (samples / "tunnel-drive.alignment.csv").string();
  s["tunnel"]["profile"] = (samples / "tunnel-drive.profile.json").string();
  return s;
}

// The scene's camera at 900 x 600 with the same field of view: the round
// replayed in a quarter of the pixels.
inline void at_900_by_600(nlohmann::json& scene) {
  auto& cam = scene["imaging"]["camera"];
  cam["width"] = 900;
  cam["height"] = 600;
  cam["fx"] = cam["fy"] = 600.0;
  cam["cx"] = 449.5;
  cam["cy"] = 299.5;
}

}  // namespace rockface::test
