#include "storage/scene/camera_json.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace rockface::storage {
namespace {

const std::string kGood = R"({ "format": "rockface-camera/1", "model": "opencv-brown",
  "width": 6000, "height": 4000, "fx": 8930.1, "fy": 8929.7, "cx": 3001.2, "cy": 1998.4,
  "distortion": [-0.1, 0.05, 0.001, -0.002, 0.01], "rms_px": 0.21,
  "body": "Nikon D7500", "lens": "18-55 @ 24 mm", "focus": "locked" })";

TEST(CameraJson, ReadsTheScenemdExample) {
  const auto c = parse_camera_json(kGood, "site.camera.json");
  EXPECT_EQ(c.width, 6000);
  EXPECT_EQ(c.height, 4000);
  EXPECT_DOUBLE_EQ(c.fx, 8930.1);
  EXPECT_DOUBLE_EQ(c.cy, 1998.4);
  EXPECT_DOUBLE_EQ(c.distortion[3], -0.002);
  EXPECT_DOUBLE_EQ(c.rms_px, 0.21);
  EXPECT_EQ(c.body, "Nikon D7500");
  EXPECT_EQ(c.focus, "locked");
}

TEST(CameraJson, WriteThenReadIsExact) {
  auto c = parse_camera_json(kGood, "a");
  c.fx = 8930.123456789012;  // JSON keeps doubles to the last bit
  const auto path = (std::filesystem::temp_directory_path() / "rockface-camera-rt.json").string();
  save_camera_json(path, c);
  const auto back = load_camera_json(path);
  EXPECT_EQ(back.fx, c.fx);
  EXPECT_EQ(back.distortion, c.distortion);
  EXPECT_EQ(back.lens, c.lens);
}

void expect_error(const std::string& text, const std::string& where,
                  const std::string& reason_part) {
  try {
    parse_camera_json(text, "site.camera.json");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), where) << e.what();
    EXPECT_NE(e.reason().find(reason_part), std::string::npos) << e.what();
  }
}

std::string with(const std::string& from, const std::string& to) {
  std::string s = kGood;
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(CameraJson, MalformedInputNamesFileAndField) {
  expect_error("{ \"format\": ", "site.camera.json", "not valid JSON");
  expect_error("[1, 2]", "site.camera.json", "JSON object");
  expect_error(with("\"rockface-camera/1\"", "\"rockface-camera/9\""), "site.camera.json: format",
               "rockface-camera/1");
  expect_error(with("\"opencv-brown\"", "\"fisheye\""), "site.camera.json: model", "opencv-brown");
  expect_error(with("\"fx\": 8930.1,", ""), "site.camera.json: fx", "missing");
  expect_error(with("8930.1", "-5"), "site.camera.json: fx", "positive");
  expect_error(with("8929.7", "\"big\""), "site.camera.json: fy", "number");
  expect_error(with("6000", "6000.5"), "site.camera.json: width", "whole number");
  expect_error(with("3001.2", "9000"), "site.camera.json: cx", "outside");
  expect_error(with("[-0.1, 0.05, 0.001, -0.002, 0.01]", "[-0.1, 0.05]"),
               "site.camera.json: distortion", "5 numbers");
  expect_error(with("-0.002", "null"), "site.camera.json: distortion[3]", "number");
  expect_error(with("0.21", "-1"), "site.camera.json: rms_px", "negative");
}

TEST(CameraJson, MissingFileIsNamed) {
  try {
    load_camera_json("/nonexistent/site.camera.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/nonexistent/site.camera.json");
  }
}

}  // namespace
}  // namespace rockface::storage
