// `rockface render` as a user runs it: the real binary, a scene file, the
// folder it writes.
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "storage/scene/camera_json.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_folders.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rockface::test::run_rockface;

fs::path work_dir() {
  const fs::path d =
      fs::temp_directory_path() / ("rockface-cli-render-" + std::to_string(::getpid()));
  fs::create_directories(d);
  rockface::test::remove_when_passed(d);
  return d;
}

// The tunnel-face sample with a small camera (800 x 600, fx 1190: the
// sample's field of view) so that the test renders in about a second.
json small_scene() {
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face.scene.json");
  json scene = json::parse(in);
  auto& cam = scene["imaging"]["camera"];
  cam["width"] = 800;
  cam["height"] = 600;
  cam["fx"] = cam["fy"] = 8930.0 * 800 / 6000;
  cam["cx"] = 399.5;
  cam["cy"] = 299.5;
  return scene;
}

std::string write_scene(const std::string& name, const json& scene) {
  const fs::path p = work_dir() / name;
  std::ofstream(p) << scene.dump(2);
  return p.string();
}

std::vector<char> bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(CliRender, WritesImagesCameraTruthAndDepth) {
  const std::string scene = write_scene("small.scene.json", small_scene());
  const fs::path out = work_dir() / "out";
  fs::remove_all(out);
  const auto r = run_rockface("render " + scene + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 of 2 target(s) visible"), std::string::npos) << r.out;
  for (const char* name : {"left.png", "right.png"}) {
    const cv::Mat img = cv::imread((out / name).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(img.cols, 800) << name;
    EXPECT_EQ(img.rows, 600);
    EXPECT_EQ(img.type(), CV_8UC3);
  }
  const cv::Mat depth = cv::imread((out / "depth-left.pfm").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth.type(), CV_32F);
  EXPECT_EQ(depth.size(), cv::Size(800, 600));
  // The face is about 10 m away along the optical axis at the image centre.
  EXPECT_NEAR(depth.at<float>(300, 400), 9.8f, 0.5f);

  const auto cam = rockface::storage::load_camera_json((out / "camera.json").string());
  EXPECT_DOUBLE_EQ(cam.fx, 8930.0 * 800 / 6000);
  EXPECT_DOUBLE_EQ(cam.distortion[0], -0.08);  // the scene switches distortion on

  std::ifstream tin(out / "truth.json");
  const json truth = json::parse(tin);
  ASSERT_EQ(truth["cameras"].size(), 2u);
  // Absolute coordinates: the datum is added back.
  EXPECT_NEAR(truth["cameras"][0]["position"][0].get<double>(), 512340.0 - 0.9, 1e-6);
  ASSERT_EQ(truth["targets"].size(), 2u);
  EXPECT_NEAR(truth["targets"][1]["centre"][2].get<double>() -
                  truth["targets"][0]["centre"][2].get<double>(),
              2.0, 1e-9);
  EXPECT_TRUE(truth["targets"][0]["visible"][0].get<bool>());
  EXPECT_GE(truth["traces"].size(), 3u);
  EXPECT_TRUE(truth["reference_line"].contains("left"));
  EXPECT_NEAR(truth["reference_line"]["azimuth_deg"].get<double>(), 90.7, 0.1);
}

TEST(CliRender, SameSceneSameFilesBitForBit) {
  const std::string scene = write_scene("again.scene.json", small_scene());
  const fs::path a = work_dir() / "a", b = work_dir() / "b";
  fs::remove_all(a);
  fs::remove_all(b);
  ASSERT_EQ(run_rockface("render " + scene + " --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run_rockface("render " + scene + " --out " + b.string()).exit_code, 0);
  for (const char* name : {"left.png", "right.png", "depth-left.pfm", "truth.json", "camera.json"})
    EXPECT_EQ(bytes_of(a / name), bytes_of(b / name)) << name;
}

TEST(CliRender, BadInputIsNamed) {
  json scene = small_scene();
  scene.erase("imaging");
  auto r = run_rockface("render " + write_scene("noimaging.scene.json", scene) + " --out " +
                        (work_dir() / "x").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("imaging"), std::string::npos) << r.err;

  scene = small_scene();
  scene["imaging"]["stations"][1]["look_at"] = scene["imaging"]["stations"][1]["position"];
  scene["imaging"]["stations"][1]["look_at"][2] = 100.0;  // straight up
  r = run_rockface("render " + write_scene("up.scene.json", scene) + " --out " +
                   (work_dir() / "x").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("imaging.stations[1]"), std::string::npos) << r.err;

  r = run_rockface("render /nonexistent/x.scene.json --out " + (work_dir() / "x").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/nonexistent/x.scene.json"), std::string::npos) << r.err;
}

}  // namespace
