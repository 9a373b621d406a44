// Where the left image has texture for dense matching (texture_mask.h): a
// picture a third rock-like texture, the rest a flat dark background with
// sensor noise; the check keeps the texture and takes the background.
#include "core/photogrammetry/matching/texture_mask.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace rockface::photogrammetry {
namespace {

// Left third: blobs of 2-8 px (uniform noise of +-40 grey levels blurred by
// 1.5 px, times 6: ~26 grey levels rms) about grey 120; the rest: grey 20
// and Gaussian noise of 2 grey levels (the mock camera's dark background),
// most of the picture as a face's frame is, so that the noise estimate's
// median falls on noise. Fixed seed.
cv::Mat third_textured(int rows, int cols) {
  cv::RNG rng(7);
  cv::Mat texture(rows, cols, CV_32F);
  rng.fill(texture, cv::RNG::UNIFORM, -40, 40);
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 1.5);
  cv::Mat noise(rows, cols, CV_32F);
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  cv::Mat f(rows, cols, CV_32F);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x)
      f.at<float>(y, x) =
          (x < cols / 3 ? 120.0f + 6 * texture.at<float>(y, x) : 20.0f) + noise.at<float>(y, x);
  cv::Mat out;
  f.convertTo(out, CV_8U);
  return out;
}

TEST(TextureMask, TheTextureIsKeptAndTheNoisyBackgroundTaken) {
  const cv::Mat image = third_textured(200, 600);
  const cv::Mat t = textured_pixels(image, {});
  // Away from the border between them by more than the window (5 px) and
  // the texture's blur (1.5 px sigma): 12 px.
  const double kept = cv::countNonZero(t(cv::Rect(0, 0, 188, 200))) / (188.0 * 200.0);
  const double taken = 1 - cv::countNonZero(t(cv::Rect(212, 0, 388, 200))) / (388.0 * 200.0);
  // The texture's variance over a 5 x 5 window (a few hundred, the blobs'
  // low frequencies left out) is ~80 times the noise's; the limit at the
  // default ratio of 3 is 10 times the noise's: one window in a thousand
  // may be that smooth. The background's windows of noise scatter about
  // the noise's variance (relative sd ~0.3 over 25 pixels): all are taken.
  EXPECT_GT(kept, 0.999);
  EXPECT_GT(taken, 0.99);
  // No check asked for: everything kept.
  EXPECT_EQ(cv::countNonZero(textured_pixels(image, {5, 0.0})), 200 * 600);
}

TEST(TextureMask, UntexturedDisparitiesAreRemoved) {
  cv::Mat d(2, 3, CV_16S, cv::Scalar(160));
  d.at<short>(0, 1) = -16;  // already invalid
  cv::Mat t(2, 3, CV_8U, cv::Scalar(255));
  t.at<std::uint8_t>(0, 1) = 0;
  t.at<std::uint8_t>(1, 2) = 0;
  EXPECT_EQ(remove_untextured(d, -16, t), 1u);
  EXPECT_EQ(d.at<short>(1, 2), -16);
  EXPECT_EQ(d.at<short>(0, 0), 160);
}

}  // namespace
}  // namespace rockface::photogrammetry
