// Dilation and erosion by a disc, spread run by run
// (proposals/disc_morphology.h), against OpenCV's own cv::dilate / cv::erode
// with the same MORPH_ELLIPSE element, pixel for pixel: the truth is
// OpenCV's output on the same image. Images: line masks (the cues' line
// images, one value on 0), masks mostly set with unset holes and borders
// (the surface's mask), non-negative float values on sparse lines (the
// cues' strengths), and the images spread by OpenCV itself (several grey
// levels, negative values); radii 1 to 21, sizes from a single pixel to
// wider than the element, so that the element runs past every edge.
#include <cstdint>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/measure/proposals/disc_morphology.h"

namespace {

namespace pr = rockface::measure::proposals;

cv::Mat element(int r) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1));
}

int differing(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::compare(a, b, diff, cv::CMP_NE);
  return cv::countNonZero(diff);
}

enum class Kind { line_mask, holed_mask, float_lines, grey_levels, signed_floats };

cv::Mat test_image(cv::Size size, Kind kind, std::uint64_t seed) {
  cv::RNG rng(seed);
  const int w = size.width, h = size.height;
  const auto point = [&] { return cv::Point(rng.uniform(0, w), rng.uniform(0, h)); };
  switch (kind) {
    case Kind::line_mask: {
      cv::Mat img = cv::Mat::zeros(size, CV_8U);
      const int value = rng.uniform(0, 2) ? 255 : rng.uniform(1, 255);
      for (int i = 0; i < 8; ++i) cv::line(img, point(), point(), cv::Scalar(value), 1);
      return img;
    }
    case Kind::holed_mask: {
      cv::Mat img(size, CV_8U, cv::Scalar(255));
      for (int i = 0; i < 4; ++i) cv::circle(img, point(), rng.uniform(1, 12), cv::Scalar(0), -1);
      img.row(0).setTo(0);  // a border off the surface along one edge
      return img;
    }
    case Kind::float_lines: {
      cv::Mat img = cv::Mat::zeros(size, CV_32F);
      for (int i = 0; i < 8; ++i)
        cv::line(img, point(), point(), cv::Scalar(rng.uniform(0.5, 40.0)), 1);
      return img;
    }
    case Kind::grey_levels: {
      cv::Mat img(size, CV_8U);
      rng.fill(img, cv::RNG::UNIFORM, 0, 256);
      return img;
    }
    case Kind::signed_floats: {
      cv::Mat img(size, CV_32F);
      rng.fill(img, cv::RNG::NORMAL, 0, 30);
      return img;
    }
  }
  return {};
}

TEST(ProposalDiscMorphology, DilatesAndErodesAsOpenCvWithItsEllipse) {
  const cv::Size sizes[] = {{97, 61}, {40, 33}, {7, 50}, {50, 5}, {1, 1}, {1, 20}, {20, 1}, {2, 2}};
  const Kind kinds[] = {Kind::line_mask, Kind::holed_mask, Kind::float_lines, Kind::grey_levels,
                        Kind::signed_floats};
  std::uint64_t seed = 0;
  for (const Kind kind : kinds)
    for (const cv::Size size : sizes)
      for (int r = 1; r <= 21; ++r) {
        const cv::Mat img = test_image(size, kind, ++seed);
        cv::Mat dilated, eroded;
        cv::dilate(img, dilated, element(r));
        cv::erode(img, eroded, element(r));
        const cv::Mat d = pr::dilate_disc(img, r), e = pr::erode_disc(img, r);
        ASSERT_EQ(d.type(), img.type());
        ASSERT_EQ(e.size(), img.size());
        EXPECT_EQ(differing(d, dilated), 0)
            << "dilate r " << r << ", " << size << ", kind " << static_cast<int>(kind);
        EXPECT_EQ(differing(e, eroded), 0)
            << "erode r " << r << ", " << size << ", kind " << static_cast<int>(kind);
      }
}

TEST(ProposalDiscMorphology, EmptyAndFullMasksAsOpenCv) {
  for (const int value : {0, 255}) {
    const cv::Mat img(30, 40, CV_8U, cv::Scalar(value));
    cv::Mat dilated, eroded;
    cv::dilate(img, dilated, element(5));
    cv::erode(img, eroded, element(5));
    EXPECT_EQ(differing(pr::dilate_disc(img, 5), dilated), 0) << value;
    EXPECT_EQ(differing(pr::erode_disc(img, 5), eroded), 0) << value;
  }
}

}  // namespace
