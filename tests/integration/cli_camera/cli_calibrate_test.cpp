// `rockface calibrate` as a user runs it: the real binary on the OpenCV
// chessboard images.
#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include "tests/support/test_paths.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "storage/scene/camera_json.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_folders.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::run_rockface;
const std::string kDir = std::string(ROCKFACE_SHARED_DIR) + "/data/calib-opencv-chessboard";

std::string left_images(int count) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kDir))
    if (e.path().filename().string().rfind("left", 0) == 0 && e.path().extension() == ".jpg")
      names.push_back(e.path().string());
  std::sort(names.begin(), names.end());
  std::string args;
  for (int i = 0; i < count && i < static_cast<int>(names.size()); ++i) args += " " + names[i];
  return args;
}

fs::path out_dir() {
  const fs::path d =
      fs::temp_directory_path() / ("rockface-cli-calibrate-" + std::to_string(::getpid()));
  fs::create_directories(d);
  rockface::test::remove_when_passed(d);
  return d;
}

TEST(CliCalibrate, WritesACameraFileMatchingTheReference) {
  const std::string out = (out_dir() / "left.camera.json").string();
  fs::remove(out);
  const auto r = run_rockface("calibrate --pattern chessboard:9x6:0.025" + left_images(13) +
                              " --out " + out + " --body \"OpenCV sample\" --focus locked");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("RMS"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("left01.jpg"), std::string::npos) << r.out;  // per-view errors listed
  const auto cam = rockface::storage::load_camera_json(out);
  cv::FileStorage fs(kDir + "/left_intrinsics.yml", cv::FileStorage::READ);
  cv::Mat K;
  fs["camera_matrix"] >> K;
  // As in the library test: the 1 % bound on fx against OpenCV's own result.
  EXPECT_NEAR(cam.fx, K.at<double>(0, 0), 0.01 * K.at<double>(0, 0));
  EXPECT_LT(cam.rms_px, 0.5);  // OpenCV reports 0.39 px on these images
  EXPECT_EQ(cam.body, "OpenCV sample");
  EXPECT_EQ(cam.focus, "locked");
}

TEST(CliCalibrate, CorruptImageIsBadInputNamingTheFile) {
  const fs::path corrupt = out_dir() / "broken.jpg";
  {
    std::ofstream f(corrupt, std::ios::binary);
    f << "\xFF\xD8 definitely not a picture";
  }
  const std::string out = (out_dir() / "never.json").string();
  fs::remove(out);
  const auto r = run_rockface("calibrate --pattern chessboard:9x6:0.025" + left_images(5) + " " +
                              corrupt.string() + " --out " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(corrupt.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));  // nothing half-made is left behind
}

TEST(CliCalibrate, TooFewViewsAndBadPatternAreBadInput) {
  const std::string out = (out_dir() / "few.json").string();
  auto r =
      run_rockface("calibrate --pattern chessboard:9x6:0.025" + left_images(2) + " --out " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("at least 3"), std::string::npos) << r.err;
  r = run_rockface("calibrate --pattern chessboard:9x6" + left_images(4) + " --out " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--pattern"), std::string::npos) << r.err;
  r = run_rockface("calibrate --pattern circles:4x11:0.02" + left_images(3) + " --out " + out);
  EXPECT_EQ(r.exit_code, 2);  // no circle grid in chessboard images
  EXPECT_NE(r.err.find("found in 0 of 3"), std::string::npos) << r.err;
}

}  // namespace
