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

// For each query keypoint: its best candidate if it passes the ratio test, else -1.
std::vector<int> guided_ratio_matches(const cv::Mat& query, const std::vector<Eigen::Vector2d>& at,
                                      const cv::Mat& train, const KeypointGrid& grid,
                                      const Eigen::Vector2d& shift, double window, double ratio) {
  std::vector<int> best(static_cast<std::size_t>(query.rows), -1);
  if (query.rows == 0 || train.rows < 2) return best;
  using Row = Eigen::Map<const Eigen::Matrix<float, 1, Eigen::Dynamic>>;
  for (int i = 0; i < query.rows; ++i) {
    const Row q(query.ptr<float>(i), query.cols);
    float d1 = std::numeric_limits<float>::infinity(), d2 = d1;
    int b1 = -1;
    grid.near(at[static_cast<std::size_t>(i)] + shift, window, [&](std::size_t j) {
      const float d = (q - Row(train.ptr<float>(static_cast<int>(j)), train.cols)).squaredNorm();
      if (d < d1) {
        d2 = d1;
        d1 = d;
        b1 = static_cast<int>(j);
      } else if (d < d2) {
        d2 = d;
      }
    });
    // The ratio of distances, as BFMatcher's knnMatch gives them (L2, not squared).
    if (b1 >= 0 && std::isfinite(d2) && std::sqrt(d1) < ratio * std::sqrt(d2))
      best[static_cast<std::size_t>(i)] = b1;
  }
  return best;
}

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
  const KeypointGrid grid_left(pl, window_px), grid_right(pr, window_px);
  const std::vector<int> lr = guided_ratio_matches(
      left.descriptors, pl, right.descriptors, grid_right, shift_px, window_px, preset.ratio_test);
  const std::vector<int> rl = guided_ratio_matches(
      right.descriptors, pr, left.descriptors, grid_left, -shift_px, window_px, preset.ratio_test);
  for (std::size_t i = 0; i < lr.size(); ++i) {
    const int j = lr[i];
    if (j < 0 || rl[static_cast<std::size_t>(j)] != static_cast<int>(i)) continue;  // mutual
    out.left.push_back(pl[i]);
    out.right.push_back(pr[static_cast<std::size_t>(j)]);
  }
  return out;
}

}  // namespace rockface::photogrammetry
