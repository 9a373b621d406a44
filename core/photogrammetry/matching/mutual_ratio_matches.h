#pragma once
// SIFT descriptors matched both ways with Lowe's ratio test, from one pass
// over their distances. The mutual check needs the left image's nearest two
// in the right and the right's nearest two in the left: two brute-force
// searches over the same distance matrix, which OpenCV's BFMatcher computes
// twice, each on one thread. Here each distance is computed once (by
// cv::batchDistance, the function BFMatcher uses, so the values and the ties
// are BFMatcher's) and the rows are shared out over the cores.
#include <vector>

#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct MutualRatioMatches {
  // For each left descriptor: its nearest right descriptor if that passes
  // the ratio test against the second nearest, else -1; and the same for
  // each right descriptor in the left.
  std::vector<int> left_to_right, right_to_left;
};

// left, right: CV_32F descriptors, one a row. ratio: the nearest distance
// must be below ratio times the second nearest (L2 distances).
MutualRatioMatches mutual_ratio_matches(const cv::Mat& left, const cv::Mat& right, double ratio);

}  // namespace rockface::photogrammetry
