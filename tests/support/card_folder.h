#pragma once
// What the card-route tests share (issue 42): a sample rendered by the mock
// camera (`rockface render`, its truth.json read back), and a camera card's
// folder made from it — the pair as the camera's JPEGs and its camera.json.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/cli_run.h"

namespace rockface::test {

// Renders tools/samples/SCENE into DIR/render; returns its truth.json.
inline nlohmann::json render_sample(const std::string& scene, const std::filesystem::path& dir) {
  const CliRun r = run_rockface("render " + std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/" +
                                scene + " --out " + (dir / "render").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(std::ifstream(dir / "render" / "truth.json"));
}

// The rendered pair in `card` as JPEGs named as a camera names them, and the
// camera's calibration beside them.
inline void write_card(const std::filesystem::path& render, const std::filesystem::path& card,
                       const std::string& left_name, const std::string& right_name) {
  std::filesystem::create_directories(card);
  const std::vector<int> quality{cv::IMWRITE_JPEG_QUALITY, 95};
  EXPECT_TRUE(cv::imwrite((card / left_name).string(), cv::imread((render / "left.png").string()),
                          quality));
  EXPECT_TRUE(cv::imwrite((card / right_name).string(), cv::imread((render / "right.png").string()),
                          quality));
  std::filesystem::copy_file(render / "camera.json", card / "camera.json");
}

}  // namespace rockface::test
