// The proposals' own Zhang-Suen thinning (proposals/line_thinning.h)
// against OpenCV's (cv::ximgproc::thinning, THINNING_ZHANGSUEN), the one it
// replaces: the truth here is OpenCV's output on the same image, pixel for
// pixel. The images are what the cues hand to the thinning: lines of one to
// nine pixels wide at every angle, crossing, touching the image's edge, and
// blobs and speckle (random disks and single pixels), from a fixed seed.
#include <cstdint>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>

#include "core/measure/proposals/line_thinning.h"

namespace {

namespace pr = rockface::measure::proposals;

cv::Mat opencv_thinning(const cv::Mat& binary) {
  cv::Mat out;
  cv::ximgproc::thinning(binary, out, cv::ximgproc::THINNING_ZHANGSUEN);
  return out;
}

int differing(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::compare(a, b, diff, cv::CMP_NE);
  return cv::countNonZero(diff);
}

// Lines of random width and direction across a w x h image, some running
// off its edges, with disks and single pixels among them.
cv::Mat line_image(int w, int h, std::uint64_t seed) {
  cv::RNG rng(seed);
  cv::Mat img = cv::Mat::zeros(h, w, CV_8U);
  for (int i = 0; i < 40; ++i) {
    const cv::Point a(rng.uniform(-20, w + 20), rng.uniform(-20, h + 20));
    const cv::Point b(rng.uniform(-20, w + 20), rng.uniform(-20, h + 20));
    cv::line(img, a, b, cv::Scalar(255), rng.uniform(1, 10),
             rng.uniform(0, 2) ? cv::LINE_8 : cv::LINE_4);
  }
  for (int i = 0; i < 15; ++i)
    cv::circle(img, cv::Point(rng.uniform(0, w), rng.uniform(0, h)), rng.uniform(1, 12),
               cv::Scalar(255), cv::FILLED);
  for (int i = 0; i < 200; ++i) img.at<std::uint8_t>(rng.uniform(0, h), rng.uniform(0, w)) = 255;
  return img;
}

TEST(ProposalLineThinning, GivesOpenCvsZhangSuenPixelForPixel) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const cv::Mat img = line_image(320 + 7 * static_cast<int>(seed), 240, seed);
    const cv::Mat expected = opencv_thinning(img);
    const cv::Mat got = pr::zhang_suen_thinning(img);
    ASSERT_EQ(got.type(), CV_8U);
    ASSERT_EQ(got.size(), img.size());
    EXPECT_EQ(differing(got, expected), 0)
        << "seed " << seed << ": " << cv::countNonZero(expected) << " pixels in OpenCV's";
    // Thinning removed something: the test compares thinned lines, not copies.
    EXPECT_LT(cv::countNonZero(expected), cv::countNonZero(img)) << "seed " << seed;
  }
}

TEST(ProposalLineThinning, FilledImagesAndTinyImagesAsOpenCv) {
  // Everything set: only the outermost rows and columns and what the
  // sub-iterations leave; an empty image; images two and three pixels
  // across, whose every pixel is on the edge or next to it.
  const cv::Mat cases[] = {cv::Mat(60, 90, CV_8U, cv::Scalar(255)), cv::Mat::zeros(50, 50, CV_8U),
                           cv::Mat(2, 40, CV_8U, cv::Scalar(255)),
                           cv::Mat(3, 3, CV_8U, cv::Scalar(255)),
                           cv::Mat(40, 3, CV_8U, cv::Scalar(255))};
  for (const cv::Mat& img : cases)
    EXPECT_EQ(differing(pr::zhang_suen_thinning(img), opencv_thinning(img)), 0)
        << img.cols << " x " << img.rows;
}

}  // namespace
