#include "core/photogrammetry/matching/mutual_ratio_matches.h"

#include <algorithm>
#include <limits>

namespace rockface::photogrammetry {

namespace {

// The nearest two distances seen so far and the nearest's index. Offered in
// increasing index, an equal distance never takes the first place: the tie
// rule of cv::batchDistance's k-nearest insertion, which BFMatcher uses.
struct RatioCandidates {
  float first = std::numeric_limits<float>::max();
  float second = std::numeric_limits<float>::max();
  int index = -1;
  void offer(float d, int i) {
    if (d < first) {
      second = first;
      first = d;
      index = i;
    } else if (d < second) {
      second = d;
    }
  }
};

// Rows of the distance matrix computed together: 256 rows of 8,000
// descriptors are 8 MB of distances.
constexpr int kBlockRows = 256;

int passing(const RatioCandidates& n, double ratio) {
  // BFMatcher's knnMatch with k = 2 gives two neighbours only when the other
  // side has two descriptors; the comparison in double as DMatch's float
  // times the double ratio.
  return n.second < std::numeric_limits<float>::max() && n.first < ratio * n.second ? n.index : -1;
}

}  // namespace

MutualRatioMatches mutual_ratio_matches(const cv::Mat& left, const cv::Mat& right, double ratio) {
  MutualRatioMatches out;
  out.left_to_right.assign(left.rows, -1);
  out.right_to_left.assign(right.rows, -1);
  // One descriptor on a side has no second nearest there: its direction
  // gives no match (as BFMatcher's), the other still does.
  if (left.empty() || right.empty()) return out;

  const int blocks = (left.rows + kBlockRows - 1) / kBlockRows;
  std::vector<RatioCandidates> rows(left.rows);
  // Each block's nearest two per right descriptor, merged in block order
  // afterwards so the result does not depend on which thread ran a block.
  std::vector<std::vector<RatioCandidates>> columns(blocks);
  cv::parallel_for_(cv::Range(0, blocks), [&](const cv::Range& range) {
    cv::Mat distances;
    for (int b = range.start; b < range.end; ++b) {
      const int r0 = b * kBlockRows, r1 = std::min(left.rows, r0 + kBlockRows);
      cv::batchDistance(left.rowRange(r0, r1), right, distances, CV_32F, cv::noArray(),
                        cv::NORM_L2);
      std::vector<RatioCandidates>& cols = columns[b];
      cols.assign(right.rows, RatioCandidates{});
      for (int i = r0; i < r1; ++i) {
        const float* d = distances.ptr<float>(i - r0);
        RatioCandidates& row = rows[i];
        for (int j = 0; j < right.rows; ++j) {
          row.offer(d[j], j);
          cols[j].offer(d[j], i);
        }
      }
    }
  });

  for (int i = 0; i < left.rows; ++i) out.left_to_right[i] = passing(rows[i], ratio);
  for (int j = 0; j < right.rows; ++j) {
    RatioCandidates n;
    for (int b = 0; b < blocks; ++b) {
      n.offer(columns[b][j].first, columns[b][j].index);
      n.offer(columns[b][j].second, -1);
    }
    out.right_to_left[j] = passing(n, ratio);
  }
  return out;
}

}  // namespace rockface::photogrammetry
