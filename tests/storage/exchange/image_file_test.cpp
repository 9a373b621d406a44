// Pictures written through the one atomic writer (storage/exchange/image_file.h):
// the same bytes as cv::imwrite, the format from the extension or given,
// and a picture that cannot be encoded refused by name, nothing left behind.
#include "storage/exchange/image_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

class ImageFile : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "rockface-image-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    image_ = cv::Mat(40, 60, CV_8UC3);
    cv::randu(image_, 0, 255);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  cv::Mat image_;
};

TEST_F(ImageFile, TheSameBytesAsImwrite) {
  for (const char* name : {"a.png", "a.jpg"}) {
    ASSERT_TRUE(cv::imwrite((dir_ / (std::string("imwrite-") + name)).string(), image_));
    write_image_file(dir_ / name, image_);
    EXPECT_EQ(bytes_of(dir_ / name), bytes_of(dir_ / (std::string("imwrite-") + name))) << name;
  }
  cv::Mat depth(20, 30, CV_32FC1);
  cv::randu(depth, 0.0f, 10.0f);
  ASSERT_TRUE(cv::imwrite((dir_ / "imwrite-depth.pfm").string(), depth));
  write_image_file(dir_ / "depth.pfm", depth);
  EXPECT_EQ(bytes_of(dir_ / "depth.pfm"), bytes_of(dir_ / "imwrite-depth.pfm"));
}

TEST_F(ImageFile, AGivenFormatOverridesTheExtension) {
  write_image_file(dir_ / "picture.out", image_, ".png");
  EXPECT_EQ(bytes_of(dir_ / "picture.out").substr(1, 3), "PNG");
}

TEST_F(ImageFile, AnEmptyPictureOrAnUnknownFormatIsRefusedByName) {
  EXPECT_THROW(write_image_file(dir_ / "empty.png", cv::Mat()), Error);
  try {
    write_image_file(dir_ / "picture.nope", image_);
    FAIL() << "an unknown format was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("picture.nope"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_)) << "nothing is left behind";
}

}  // namespace
}  // namespace rockface::storage
