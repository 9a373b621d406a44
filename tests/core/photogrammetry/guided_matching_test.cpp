// Guided matching (guided_matching.h): with the coarse shift of two
// photographs known, comparing each keypoint only with those in a window
// around its predicted place keeps every brute-force match that lies in the
// window (its best candidate is there, and the window's second best is no
// closer than the whole photograph's), and finds no match that breaks the
// shift by more than the window.
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "core/photogrammetry/matching/guided_matching.h"
#include "core/photogrammetry/matching/image_overlap.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "tests/core/photogrammetry/noise_texture.h"

namespace {

using namespace rockface;
using namespace rockface::photogrammetry;

TEST(GuidedMatching, KeepsTheBruteForceMatchesInsideTheWindow) {
  const cv::Mat strip = test::noise_texture(1200, 400, 21, 1.5, 8.0);
  const cv::Mat left = strip(cv::Rect(0, 0, 800, 400)).clone();
  const cv::Mat right = strip(cv::Rect(300, 0, 800, 400)).clone();
  const ReconstructionPreset preset = preset_fast();
  const ImageFeatures l = detect_features(left, 1.0, preset);
  const ImageFeatures r = detect_features(right, 1.0, preset);
  const CoarseOverlap coarse = coarse_overlap(make_thumbnail(left), make_thumbnail(right));
  // One thumbnail pixel is 800 / 256 = 3.1 px: the shift to a few pixels.
  ASSERT_NEAR(coarse.shift_px.x(), -300, 4.0);
  const double window = 0.1 * left.cols;
  const FeatureMatches guided = match_guided(l, r, coarse.shift_px, window, preset);
  const FeatureMatches all = match_detected(l, r, preset);
  auto key = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::make_pair(std::make_pair(a.x(), a.y()), std::make_pair(b.x(), b.y()));
  };
  std::set<decltype(key(guided.left[0], guided.right[0]))> found;
  for (std::size_t k = 0; k < guided.size(); ++k) {
    found.insert(key(guided.left[k], guided.right[k]));
    // Within the window of the coarse shift, by construction.
    EXPECT_LE((guided.right[k] - guided.left[k] - coarse.shift_px).cwiseAbs().maxCoeff(),
              window + 1e-9);
  }
  int inside = 0, kept = 0;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if ((all.right[k] - all.left[k] - coarse.shift_px).cwiseAbs().maxCoeff() > window) continue;
    ++inside;
    kept += found.count(key(all.left[k], all.right[k])) > 0;
  }
  ASSERT_GT(inside, 200);  // 60 % overlap of a rich texture
  EXPECT_EQ(kept, inside);
  // Fewer distractors in the window: at least as many matches as brute force.
  EXPECT_GE(guided.size(), static_cast<std::size_t>(inside));
}

}  // namespace
