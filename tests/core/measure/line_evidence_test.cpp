// The cues' hysteresis (proposals/line_evidence.h): the 8-connected groups of
// the kept pixels that hold a seed, against the groups OpenCV's own
// labelling finds (cv::connectedComponents, 8-connected) on the same images:
// lines, blobs and speckle at random (fixed seeds), groups touching the
// image's edge and each other only at a corner, seeds off the kept pixels.
#include <cstdint>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/measure/proposals/line_evidence.h"

namespace {

namespace pr = rockface::measure::proposals;

// What the groups OpenCV labels give: every kept pixel of a group with at
// least one pixel both kept and seeded.
cv::Mat seeded_groups(const cv::Mat& keep, const cv::Mat& seed) {
  cv::Mat labels;
  const int n = cv::connectedComponents(keep, labels, 8, CV_32S);
  std::vector<bool> seeded(static_cast<std::size_t>(n), false);
  for (int r = 0; r < keep.rows; ++r)
    for (int c = 0; c < keep.cols; ++c)
      if (keep.at<std::uint8_t>(r, c) && seed.at<std::uint8_t>(r, c))
        seeded[static_cast<std::size_t>(labels.at<int>(r, c))] = true;
  cv::Mat out(keep.size(), CV_8U, cv::Scalar(0));
  for (int r = 0; r < keep.rows; ++r)
    for (int c = 0; c < keep.cols; ++c) {
      const int label = labels.at<int>(r, c);
      if (label > 0 && seeded[static_cast<std::size_t>(label)]) out.at<std::uint8_t>(r, c) = 255;
    }
  return out;
}

int differing(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::compare(a, b, diff, cv::CMP_NE);
  return cv::countNonZero(diff);
}

TEST(ProposalHysteresis, KeepsTheSeededGroupsOpenCvLabels) {
  for (std::uint64_t s = 1; s <= 10; ++s) {
    cv::RNG rng(s);
    const int w = 300 + 11 * static_cast<int>(s), h = 220;
    cv::Mat keep = cv::Mat::zeros(h, w, CV_8U), seed = cv::Mat::zeros(h, w, CV_8U);
    for (int i = 0; i < 60; ++i)
      cv::line(keep, cv::Point(rng.uniform(-10, w + 10), rng.uniform(-10, h + 10)),
               cv::Point(rng.uniform(-10, w + 10), rng.uniform(-10, h + 10)), cv::Scalar(255),
               rng.uniform(1, 4), cv::LINE_8);
    for (int i = 0; i < 2000; ++i)
      keep.at<std::uint8_t>(rng.uniform(0, h), rng.uniform(0, w)) = 255;
    // Seeds anywhere: on kept pixels (they seed their group) and off them
    // (they seed nothing).
    for (int i = 0; i < 25; ++i) seed.at<std::uint8_t>(rng.uniform(0, h), rng.uniform(0, w)) = 255;
    const cv::Mat expected = seeded_groups(keep, seed);
    EXPECT_EQ(differing(pr::hysteresis(keep, seed), expected), 0) << "seed " << s;
    EXPECT_GT(cv::countNonZero(expected), 0) << "seed " << s << ": no group seeded";
    EXPECT_LT(cv::countNonZero(expected), cv::countNonZero(keep)) << "seed " << s;
  }
}

TEST(ProposalHysteresis, GroupsMeetingAtACornerAreOneAndEdgesAreNoWall) {
  // Two diagonal runs touching corner to corner (one 8-connected group) and
  // a column down the image's right edge, seeded at its foot.
  cv::Mat keep = cv::Mat::zeros(20, 20, CV_8U), seed = cv::Mat::zeros(20, 20, CV_8U);
  for (int i = 0; i < 5; ++i) keep.at<std::uint8_t>(i, i) = 255;
  keep.at<std::uint8_t>(5, 5) = 255;  // (row, column): on from (4, 4) corner to corner
  keep.at<std::uint8_t>(6, 4) = 255;
  seed.at<std::uint8_t>(6, 4) = 255;
  for (int r = 0; r < 20; ++r) keep.at<std::uint8_t>(r, 19) = 255;
  seed.at<std::uint8_t>(19, 19) = 255;
  keep.at<std::uint8_t>(15, 10) = 255;  // alone, not seeded
  const cv::Mat got = pr::hysteresis(keep, seed);
  EXPECT_EQ(differing(got, seeded_groups(keep, seed)), 0);
  EXPECT_EQ(got.at<std::uint8_t>(0, 0), 255);  // reached from (6, 4) over the corner
  EXPECT_EQ(got.at<std::uint8_t>(0, 19), 255);
  EXPECT_EQ(got.at<std::uint8_t>(15, 10), 0);
}

}  // namespace
