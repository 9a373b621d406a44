#pragma once
// Picks as a geologist would tap them, taken from the true traces that
// `rockface render` writes in truth.json (their pixels in the left
// photograph), on a demo face whose keyblock lies wholly in the photograph:
// for the measure and replay suites.
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include "tests/support/test_paths.h"

#include <nlohmann/json.hpp>

namespace rockface::test {

// The demo tunnel face (tools/samples/tunnel-face-demo.scene.json) without
// its picks, for suites that pick their own. The sample's compass line lies
// on the face (off it, the registration, which finds the line's ends on the
// reconstructed surface, turned north by ~1.7 deg, more than the 1 deg these
// suites hold measured planes to), and its joints are placed so that the
// keyblock's lowest corner (J1 x J2 on the face) is in the photograph: a
// block can only be mapped from what the photograph shows.
inline nlohmann::json demo_scene() {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene.erase("picks");
  return scene;
}

struct TruthTrace {
  std::string joint, patch;
  std::vector<std::array<double, 2>> pixels;  // inside the mapped part of the image
};

// The true traces on the tunnel face (patches FACE_W, FACE_E) with at least
// 20 pixels more than 80 px from the left and right borders and 30 px from
// the top and bottom: dense matching leaves the borders without surface
// (the disparity search at the sides), and the side walls and floor are
// seen at grazing angles, with holes.
inline std::vector<TruthTrace> face_traces(const std::filesystem::path& truth_json) {
  std::ifstream in(truth_json);
  const nlohmann::json truth = nlohmann::json::parse(in);
  const double w = truth.at("intrinsics").at("width").get<double>();
  const double h = truth.at("intrinsics").at("height").get<double>();
  std::vector<TruthTrace> out;
  for (const auto& t : truth.at("traces")) {
    TruthTrace tt;
    tt.joint = t.at("joint").get<std::string>();
    tt.patch = t.value("patch", "");
    if (tt.patch.rfind("FACE", 0) != 0) continue;
    for (const auto& p : t.at("left_image")) {
      const double u = p[0].get<double>(), v = p[1].get<double>();
      if (u > 80 && v > 30 && u < w - 81 && v < h - 31) tt.pixels.push_back({u, v});
    }
    if (tt.pixels.size() >= 20) out.push_back(std::move(tt));
  }
  return out;
}

// `taps` pixels spread evenly along the trace, ends included.
inline nlohmann::json taps_along(const TruthTrace& t, std::size_t taps) {
  nlohmann::json a = nlohmann::json::array();
  const std::size_t n = t.pixels.size();
  for (std::size_t k = 0; k < taps; ++k) {
    const auto& p = t.pixels[std::min(n - 1, k * (n - 1) / std::max<std::size_t>(1, taps - 1))];
    a.push_back({p[0], p[1]});
  }
  return a;
}

// Eight taps along every face trace (T1, T2, ... with their joint), and the
// longest J1 piece once more traced semi-automatically between its ends (S1).
inline nlohmann::json face_picks(const std::vector<TruthTrace>& traces) {
  nlohmann::json picks = nlohmann::json::array();
  const TruthTrace* longest = nullptr;
  for (const auto& t : traces) {
    picks.push_back({{"id", "T" + std::to_string(picks.size() + 1)},
                     {"joint", t.joint},
                     {"photo", "left"},
                     {"pixels", taps_along(t, 8)}});
    if (t.joint == "J1" && (!longest || t.pixels.size() > longest->pixels.size())) longest = &t;
  }
  if (longest)
    picks.push_back({{"id", "S1"},
                     {"joint", "J1"},
                     {"photo", "left"},
                     {"ends", taps_along(*longest, 2)},
                     {"cost", "darkness"}});
  return picks;
}

}  // namespace rockface::test
