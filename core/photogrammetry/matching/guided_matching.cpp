#include "core/photogrammetry/matching/guided_matching.h"

#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace rockface::photogrammetry {

namespace {

// Pixel centres map as (x + 0.5) / s - 0.5 between scales (OpenCV's resize
// convention), as in match_detected().
std::vector<Eigen::Vector2d> full_positions(const ImageFeatures& f) {
  std::vector<Eigen::Vector2d> out;
  out.reserve(f.keypoints.size());
  const double inv = 1.0 / f.scale;
  for (const auto& k : f.keypoints)
    out.emplace_back((k.pt.x + 0.5) * inv - 0.5, (k.pt.y + 0.5) * inv - 0.5);
  return out;
}

// The keypoints of one photograph by square cells of the window's size: the
// candidates of a query are in the 3 x 3 cells around its predicted place.
class KeypointGrid {
 public:
  KeypointGrid(const std::vector<Eigen::Vector2d>& points, double cell)
      : points_(points), cell_(cell) {
    for (std::size_t i = 0; i < points.size(); ++i) cells_[key(cell_of(points[i]))].push_back(i);
  }

  template <typename F>
  void near(const Eigen::Vector2d& q, double window, F&& f) const {
    const Eigen::Vector2i c = cell_of(q);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find(key(c + Eigen::Vector2i(dx, dy)));
        if (it == cells_.end()) continue;
        for (const std::size_t i : it->second)
          if ((points_[i] - q).cwiseAbs().maxCoeff() <= window) f(i);
      }
  }

 private:
  Eigen::Vector2i cell_of(const Eigen::Vector2d& p) const {
    return {static_cast<int>(std::floor(p.x() / cell_)),
            static_cast<int>(std::floor(p.y() / cell_))};
  }
  static long long key(const Eigen::Vector2i& c) {
    return (static_cast<long long>(c.x()) << 32) ^ static_cast<unsigned int>(c.y());
  }
  const std::vector<Eigen::Vector2d>& points_;
  double cell_;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

// The nearest and second-nearest candidate of one keypoint (squared
// distances), as the candidates are offered.
struct NearestTwo {
  float d1 = std::numeric_limits<float>::infinity(), d2 = d1;
  int b1 = -1;
  void offer(float d, int j) {
    if (d < d1) {
      d2 = d1;
      d1 = d;
      b1 = j;
    } else if (d < d2) {
      d2 = d;
    }
  }
  // Its best candidate if it passes the ratio test (of distances, as
  // BFMatcher's knnMatch gives them: L2, not squared), else -1.
  int passing(double ratio) const {
    return b1 >= 0 && std::isfinite(d2) && std::sqrt(d1) < ratio * std::sqrt(d2) ? b1 : -1;
  }
};

}  // namespace

FeatureMatches match_guided(const ImageFeatures& left, const ImageFeatures& right,
                            const Eigen::Vector2d& shift_px, double window_px,
                            const ReconstructionPreset& preset) {
  FeatureMatches out;
  out.keypoints_left = static_cast<int>(left.keypoints.size());
  out.keypoints_right = static_cast<int>(right.keypoints.size());
  if (left.descriptors.empty() || right.descriptors.empty()) return out;
  CV_Assert(left.descriptors.type() == CV_32F && right.descriptors.type() == CV_32F);
  const auto pl = full_positions(left), pr = full_positions(right);
  // A left keypoint i and a right one j are candidates of each other when
  // j lies within the window around where the shift puts i (the same
  // condition as i within the window around j moved back), so each
  // candidate pair's distance is computed once and offered to both: the
  // left-to-right and right-to-left searches of the mutual check in one
  // pass, half the descriptor distances of two.
  const KeypointGrid grid_right(pr, window_px);
  std::vector<NearestTwo> from_left(pl.size()), from_right(pr.size());
  const cv::Mat& ld = left.descriptors;
  const cv::Mat& rd = right.descriptors;
  using Row = Eigen::Map<const Eigen::Matrix<float, 1, Eigen::Dynamic>>;
  for (int i = 0; i < ld.rows; ++i) {
    const Row q(ld.ptr<float>(i), ld.cols);
    NearestTwo& mine = from_left[static_cast<std::size_t>(i)];
    grid_right.near(pl[static_cast<std::size_t>(i)] + shift_px, window_px, [&](std::size_t j) {
      const int k = static_cast<int>(j);
      const float d = (q - Row(rd.ptr<float>(k), rd.cols)).squaredNorm();
      mine.offer(d, k);
      from_right[j].offer(d, i);
    });
  }
  std::vector<int> lr(pl.size()), rl(pr.size());
  for (std::size_t i = 0; i < pl.size(); ++i) lr[i] = from_left[i].passing(preset.ratio_test);
  for (std::size_t j = 0; j < pr.size(); ++j) rl[j] = from_right[j].passing(preset.ratio_test);
  for (std::size_t i = 0; i < lr.size(); ++i) {
    const int j = lr[i];
    if (j < 0 || rl[static_cast<std::size_t>(j)] != static_cast<int>(i)) continue;  // mutual
    out.left.push_back(pl[i]);
    out.right.push_back(pr[static_cast<std::size_t>(j)]);
  }
  return out;
}

}  // namespace rockface::photogrammetry
