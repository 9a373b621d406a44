// The coarse overlap of two photographs (image_overlap.h), which orders the
// merge's matching: two crops of one rock texture shifted along the face
// are found shifted by that much, with a clear peak; crops of two unrelated
// textures score far lower than any real overlap.
#include <gtest/gtest.h>

#include "core/photogrammetry/matching/image_overlap.h"
#include "tests/core/photogrammetry/noise_texture.h"

namespace {

using namespace rockface;
using photogrammetry::coarse_overlap;
using photogrammetry::make_thumbnail;

// The strip of rock the stations move along, 1200 x 800 photographs of it.
const cv::Mat& strip() {
  static const cv::Mat t = test::noise_texture(3200, 800, 11, 2.0, 12.0);
  return t;
}

cv::Mat photograph_at(int x) {
  return strip()(cv::Rect(x, 0, 1200, 800)).clone();
}

TEST(ImageOverlap, AShiftAlongTheFaceIsFoundWithItsOverlap) {
  const auto a = make_thumbnail(photograph_at(600));
  for (const int shift : {200, 400, 800}) {
    SCOPED_TRACE(shift);
    const auto o = coarse_overlap(a, make_thumbnail(photograph_at(600 + shift)));
    // One thumbnail pixel is 1200 / 256 = 4.7 photograph pixels; phase
    // correlation finds the peak to a fraction of that.
    EXPECT_NEAR(o.shift_px.x(), -shift, 5.0);
    EXPECT_NEAR(o.shift_px.y(), 0, 5.0);
    EXPECT_NEAR(o.fraction, 1 - shift / 1200.0, 0.01);  // 5 px of 1200
    EXPECT_GT(o.response, 0.15);  // 0.23 at a third in common (image_overlap.h)
  }
}

TEST(ImageOverlap, MoreOverlapScoresHigherAndUnrelatedRockScoresLowest) {
  const auto a = make_thumbnail(photograph_at(600));
  const double near = coarse_overlap(a, make_thumbnail(photograph_at(800))).score();
  const double far = coarse_overlap(a, make_thumbnail(photograph_at(1400))).score();
  const cv::Mat other = test::noise_texture(1200, 800, 99, 2.0, 12.0);
  const double unrelated = coarse_overlap(a, make_thumbnail(other)).score();
  EXPECT_GT(near, far);
  // Noise against noise correlates by chance only (peaks of 0.04-0.05
  // measured, against 0.23 for a third of a frame in common):
  // several times lower.
  EXPECT_LT(unrelated * 3, far);
}

TEST(ImageOverlap, PhotographsOfDifferentSizesHaveNoOverlapToOrderBy) {
  const auto a = make_thumbnail(photograph_at(0));
  const auto b = make_thumbnail(strip()(cv::Rect(0, 0, 1200, 600)).clone());
  EXPECT_EQ(coarse_overlap(a, b).score(), 0.0);
}

}  // namespace
