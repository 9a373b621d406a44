// SIFT on an image above the tile limit (kMaxSiftTilePixels, 2 Mpx at the
// working scale) runs tile by tile to bound memory: the tiles must not
// change what a caller gets - keypoints once each, spread over the whole
// image, the feature budget kept, and matches that recover a known shift.
#include <cmath>
#include <map>
#include <utility>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "tests/core/photogrammetry/noise_texture.h"

namespace rp = rockface::photogrammetry;

namespace {

TEST(FeatureTiles, TiledDetectionMatchesAKnownShiftOverTheWholeImage) {
  const int w = 2400, h = 1000, dx = 37, dy = 11;
  // 2400 x 1000 (2.4 Mpx: a 2 x 2 grid of tiles), cut twice with a known shift.
  const cv::Mat big = rockface::test::noise_texture(w + dx, h + dy, 5, 1.5, 8.0);
  const cv::Mat left = big(cv::Rect(dx, dy, w, h)).clone();
  const cv::Mat right =
      big(cv::Rect(0, 0, w, h)).clone();  // left pixel (x, y) is right (x+dx, y+dy)
  rp::ReconstructionPreset preset = rp::preset_standard();
  preset.feature_max_width = 0;  // full size: 2.4 Mpx, tiled 2 x 2
  rockface::NoProgress progress;
  const rp::FeatureMatches m = rp::match_features(left, right, preset, progress);

  // The budget holds over the tiles. SIFT keeps every keypoint tied with
  // the last one it retains (orientation copies share a response), in each
  // tile as in one piece: 0.7 % over on this image, 2 % allowed.
  EXPECT_LE(m.keypoints_left, preset.max_features * 102 / 100);
  EXPECT_GT(m.keypoints_left, preset.max_features * 9 / 10);
  ASSERT_GT(m.size(), 1000u);

  std::map<std::pair<int, int>, int> at;  // matches per quarter-pixel position
  int quadrant[2][2] = {{0, 0}, {0, 0}};
  int off = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    // SIFT positions on a pure translation: sub-pixel, well under 0.5 px.
    const Eigen::Vector2d d = m.right[i] - m.left[i];
    if ((d - Eigen::Vector2d(dx, dy)).norm() > 0.5) ++off;
    ++at[{static_cast<int>(std::lround(m.left[i].x() * 4)),
          static_cast<int>(std::lround(m.left[i].y() * 4))}];
    ++quadrant[m.left[i].y() < h / 2.0][m.left[i].x() < w / 2.0];
  }
  // Mutual best matches with the ratio test on a translated copy: a handful
  // of repetitive-texture confusions at most.
  EXPECT_LT(off, static_cast<int>(m.size() / 100));
  // Each keypoint belongs to one tile. SIFT alone repeats a position for a
  // second orientation (about a quarter of them here); a keypoint taken from
  // two overlapping tiles would double the repeats near the seams (x = 1200,
  // y = 500, within the 96 px context). Near and far rates are each
  // measured on over a thousand matches (1-sigma ~1.5 %): 1.5 x allowed.
  double near[2] = {0, 0}, far[2] = {0, 0};  // {positions, repeated}
  for (const auto& [p, n] : at) {
    const double x = p.first / 4.0, y = p.second / 4.0;
    double* bin = std::abs(x - w / 2.0) < 96 || std::abs(y - h / 2.0) < 96 ? near : far;
    bin[0] += 1;
    bin[1] += n > 1 ? 1 : 0;
  }
  ASSERT_GT(near[0], 500);
  EXPECT_LT(near[1] / near[0], 1.5 * far[1] / far[0]);
  // Every tile contributes (each holds a quarter of the image).
  for (auto& row : quadrant)
    for (int q : row) EXPECT_GT(q, static_cast<int>(m.size() / 8));
}

}  // namespace
