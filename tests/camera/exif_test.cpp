#include "camera/exif.h"
#include "tests/support/test_paths.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"

namespace rockface::camera {
namespace {

std::vector<uint8_t> small_jpeg() {
  cv::Mat img(48, 64, CV_8UC3, cv::Scalar(40, 120, 200));
  std::vector<uint8_t> jpeg;
  cv::imencode(".jpg", img, jpeg);
  return jpeg;
}

ExifInfo full_info() {
  ExifInfo e;
  e.make = "NIKON CORPORATION";
  e.model = "NIKON D7500";
  e.lens = "18.0-55.0 mm f/3.5-5.6";
  e.serial = "3012345";
  e.datetime = "2026:05:17 09:41:07";
  e.focal_length_mm = 24.0;
  e.f_number = 8.0;
  e.exposure_time_s = 1.0 / 125;
  e.iso = 200;
  e.flash_fired = false;
  e.focus_distance_m = 10.5;
  e.width = 6000;
  e.height = 4000;
  return e;
}

TEST(Exif, RoundTripKeepsEveryFieldTheWorkflowNeeds) {
  const auto jpeg = with_exif(small_jpeg(), full_info());
  const ExifInfo e = read_exif(jpeg);
  EXPECT_EQ(e.make, "NIKON CORPORATION");
  EXPECT_EQ(e.model, "NIKON D7500");
  EXPECT_EQ(e.lens, "18.0-55.0 mm f/3.5-5.6");
  EXPECT_EQ(e.serial, "3012345");  // which body: its calibration (issue 42)
  EXPECT_EQ(e.datetime, "2026:05:17 09:41:07");
  // Rationals over 10^6: exact for these values up to double rounding.
  EXPECT_NEAR(*e.focal_length_mm, 24.0, 1e-9);
  EXPECT_NEAR(*e.f_number, 8.0, 1e-9);
  EXPECT_NEAR(*e.exposure_time_s, 0.008, 1e-9);
  EXPECT_NEAR(*e.focus_distance_m, 10.5, 1e-9);
  EXPECT_EQ(*e.iso, 200);
  EXPECT_FALSE(*e.flash_fired);
  EXPECT_EQ(*e.width, 6000);
  EXPECT_EQ(*e.height, 4000);
  // What it says of its camera, for its calibration.
  const auto camera = photo_camera(e);
  EXPECT_EQ(camera.described(),
            "NIKON D7500 (serial 3012345), lens 18.0-55.0 mm f/3.5-5.6 at 24 mm, 6000 x 4000 px");
  // The image itself still decodes.
  const cv::Mat decoded = cv::imdecode(jpeg, cv::IMREAD_COLOR);
  EXPECT_EQ(decoded.cols, 64);
}

TEST(Exif, RewritingReplacesTheOldBlock) {
  auto info = full_info();
  auto jpeg = with_exif(small_jpeg(), info);
  info.focal_length_mm = 35.0;
  info.flash_fired = true;
  jpeg = with_exif(jpeg, info);
  const ExifInfo e = read_exif(jpeg);
  EXPECT_NEAR(*e.focal_length_mm, 35.0, 1e-9);
  EXPECT_TRUE(*e.flash_fired);
}

TEST(Exif, NoExifGivesAnEmptyRecord) {
  EXPECT_TRUE(read_exif(small_jpeg()).empty());
  // The OpenCV sample images carry no EXIF either.
  EXPECT_TRUE(
      read_exif_file(std::string(ROCKFACE_SHARED_DIR) + "/data/calib-opencv-chessboard/left01.jpg")
          .empty());
}

TEST(Exif, DamagedBlockIsNotTrusted) {
  auto jpeg = with_exif(small_jpeg(), full_info());
  // Cut the file inside the EXIF block: whatever is read must not crash,
  // and the values cut away are absent, not garbage.
  jpeg.resize(40);
  const ExifInfo e = read_exif(jpeg);
  if (e.focal_length_mm) {
    EXPECT_NEAR(*e.focal_length_mm, 24.0, 1e-9);
  }
  std::vector<uint8_t> noise(500);
  for (size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<uint8_t>(i * 37 + 11);
  EXPECT_NO_THROW(read_exif(noise));
  EXPECT_THROW(with_exif(noise, full_info()), Error);
}

TEST(Exif, MissingFileIsNamed) {
  try {
    read_exif_file("/nonexistent/DSC_0001.JPG");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/nonexistent/DSC_0001.JPG");
  }
}

}  // namespace
}  // namespace rockface::camera
