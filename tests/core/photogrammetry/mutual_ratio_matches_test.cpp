#include "core/photogrammetry/matching/mutual_ratio_matches.h"

#include <gtest/gtest.h>
#include <opencv2/features2d.hpp>

namespace rockface::photogrammetry {
namespace {

// What the matcher replaced: OpenCV's brute-force k-nearest search, one
// direction at a time, and Lowe's ratio test on its two neighbours.
std::vector<int> bf_ratio(const cv::Mat& query, const cv::Mat& train, double ratio) {
  std::vector<int> best(query.rows, -1);
  if (query.rows == 0 || train.rows < 2) return best;
  cv::BFMatcher matcher(cv::NORM_L2);
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(query, train, knn, 2);
  for (const auto& m : knn)
    if (m.size() == 2 && m[0].distance < ratio * m[1].distance) best[m[0].queryIdx] = m[0].trainIdx;
  return best;
}

// SIFT-like descriptors: 128 non-negative components, a share of the right
// ones noisy copies of left ones (so the ratio test passes for some), and
// exact duplicates (so ties occur, where the tie rule must be BFMatcher's).
std::pair<cv::Mat, cv::Mat> descriptors(int left_rows, int right_rows, unsigned seed) {
  cv::RNG rng(seed);
  cv::Mat left(left_rows, 128, CV_32F), right(right_rows, 128, CV_32F);
  rng.fill(left, cv::RNG::UNIFORM, 0.0, 60.0);
  rng.fill(right, cv::RNG::UNIFORM, 0.0, 60.0);
  for (int j = 0; j < right_rows; j += 2) {
    const int i = rng.uniform(0, left_rows);
    cv::Mat noise(1, 128, CV_32F);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 3.0);
    right.row(j) = left.row(i) + noise;
  }
  // Duplicates on both sides: equal distances to two candidates.
  if (right_rows >= 4) right.row(1).copyTo(right.row(3));
  if (left_rows >= 600) left.row(5).copyTo(left.row(590));  // in another block of rows
  return {left, right};
}

TEST(MutualRatioMatches, GivesBruteForceMatchesBothWaysIncludingTies) {
  // Sizes around the 256-row blocks, and the degenerate ones.
  const std::vector<std::pair<int, int>> sizes = {{1, 5},    {2, 2},     {5, 1},     {40, 60},
                                                  {256, 90}, {257, 300}, {700, 650}, {1500, 1200}};
  unsigned seed = 7;
  for (const auto& [n, m] : sizes) {
    const auto [left, right] = descriptors(n, m, seed++);
    for (const double ratio : {0.8, 0.9, 1.0}) {
      const MutualRatioMatches got = mutual_ratio_matches(left, right, ratio);
      // Exactly equal: the same distances (cv::batchDistance) and tie rule.
      EXPECT_EQ(got.left_to_right, bf_ratio(left, right, ratio)) << n << " x " << m << " " << ratio;
      const std::vector<int> rl = bf_ratio(right, left, ratio);
      // BFMatcher with one left descriptor answers no right one; so does this.
      EXPECT_EQ(got.right_to_left, rl) << n << " x " << m << " " << ratio;
    }
  }
}

TEST(MutualRatioMatches, FindsTheNoisyCopies) {
  const auto [left, right] = descriptors(500, 400, 99);
  const MutualRatioMatches got = mutual_ratio_matches(left, right, 0.8);
  int mutual = 0;
  for (int i = 0; i < left.rows; ++i) {
    const int j = got.left_to_right[i];
    if (j >= 0 && got.right_to_left[j] == i) ++mutual;
  }
  // 200 right rows are copies with noise σ 3 of a left row, against ~0.7
  // random rows' distance of ~245: every copy is found unless two copies
  // share their left row (then neither is unique): at least 150 of 200.
  EXPECT_GE(mutual, 150);
  EXPECT_LE(mutual, 200);
}

}  // namespace
}  // namespace rockface::photogrammetry
