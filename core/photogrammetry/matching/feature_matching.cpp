#include "core/photogrammetry/matching/feature_matching.h"

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <future>

#include "core/common/error.h"
#include "core/photogrammetry/matching/mutual_ratio_matches.h"

namespace rockface::photogrammetry {

cv::Mat to_grey(const cv::Mat& image) {
  if (image.empty()) throw InputError("image", "empty image");
  if (image.depth() != CV_8U) throw InputError("image", "expected 8-bit pixels");
  cv::Mat grey;
  if (image.channels() == 1)
    grey = image;
  else if (image.channels() == 3)
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else if (image.channels() == 4)
    cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  else
    throw InputError("image", "expected 1, 3 or 4 channels");
  return grey;
}

namespace {

// The widest working image whose two images' features are detected at once
// (the standard preset's): two tiles' scale spaces live together then.
constexpr int kFeaturesSideBySideMaxWidth = 2400;

// OpenCV's SIFT doubles its input and keeps about a dozen float images of
// that size: ~45 bytes per input pixel, 1.9 GB for the precise preset's
// 4000 px working width. Larger images are detected tile by tile, which
// bounds that to ~90 MB per million tile pixels whatever the image size.
constexpr double kMaxSiftTilePixels = 2.0e6;
// Context around a tile's core: keypoints are kept only in the core, at
// least this far from the tile's cut edges, so their descriptors (radius
// ~10.6 sigma) see the same pixels as in one piece up to sigma ~9 px.
constexpr int kSiftTileMargin = 96;

ImageFeatures detect(const cv::Mat& image, double scale, const ReconstructionPreset& preset) {
  cv::Mat grey = to_grey(image);
  if (scale != 1.0) cv::resize(grey, grey, cv::Size(), scale, scale, cv::INTER_AREA);
  ImageFeatures d;
  d.scale = scale;
  const double pixels = static_cast<double>(grey.total());
  const int tiles = static_cast<int>(std::ceil(std::sqrt(pixels / kMaxSiftTilePixels)));
  if (tiles <= 1) {
    auto sift = cv::SIFT::create(preset.max_features, 3, preset.sift_contrast);
    sift->detectAndCompute(grey, cv::noArray(), d.keypoints, d.descriptors);
    return d;
  }
  // A tiles x tiles grid; each tile's share of the feature budget follows
  // its area (0 = no limit stays no limit).
  std::vector<cv::Mat> descriptors;
  for (int ty = 0; ty < tiles; ++ty)
    for (int tx = 0; tx < tiles; ++tx) {
      const cv::Rect core(tx * grey.cols / tiles, ty * grey.rows / tiles,
                          (tx + 1) * grey.cols / tiles - tx * grey.cols / tiles,
                          (ty + 1) * grey.rows / tiles - ty * grey.rows / tiles);
      const cv::Rect outer =
          cv::Rect(core.x - kSiftTileMargin, core.y - kSiftTileMargin,
                   core.width + 2 * kSiftTileMargin, core.height + 2 * kSiftTileMargin) &
          cv::Rect(0, 0, grey.cols, grey.rows);
      const double share = static_cast<double>(core.area()) / pixels;
      const int budget =
          preset.max_features > 0 ? static_cast<int>(std::ceil(preset.max_features * share)) : 0;
      // Detect with a larger budget in the context, then keep the core's.
      const int detect_budget =
          budget > 0 ? static_cast<int>(std::ceil(budget * static_cast<double>(outer.area()) /
                                                  static_cast<double>(core.area())))
                     : 0;
      auto sift = cv::SIFT::create(detect_budget, 3, preset.sift_contrast);
      std::vector<cv::KeyPoint> kp;
      cv::Mat desc;
      sift->detectAndCompute(grey(outer), cv::noArray(), kp, desc);
      for (int i = 0; i < static_cast<int>(kp.size()); ++i) {
        cv::KeyPoint k = kp[i];
        k.pt += cv::Point2f(static_cast<float>(outer.x), static_cast<float>(outer.y));
        if (!core.contains(cv::Point(static_cast<int>(std::floor(k.pt.x)),
                                     static_cast<int>(std::floor(k.pt.y)))))
          continue;
        d.keypoints.push_back(k);
        descriptors.push_back(desc.row(i));
      }
    }
  if (!descriptors.empty()) cv::vconcat(descriptors, d.descriptors);
  return d;
}

}  // namespace

ImageFeatures detect_features(const cv::Mat& image, double scale,
                              const ReconstructionPreset& preset) {
  return detect(image, scale, preset);
}

namespace {

FeatureMatches match(const ImageFeatures& l, const ImageFeatures& r,
                     const ReconstructionPreset& preset, Progress& progress) {
  progress.step("features: matching", 0.6);
  const MutualRatioMatches both =
      mutual_ratio_matches(l.descriptors, r.descriptors, preset.ratio_test);
  const std::vector<int>& lr = both.left_to_right;
  const std::vector<int>& rl = both.right_to_left;
  progress.step("features: mutual check", 0.9);

  FeatureMatches out;
  out.keypoints_left = static_cast<int>(l.keypoints.size());
  out.keypoints_right = static_cast<int>(r.keypoints.size());
  // Pixel centres map as (x + 0.5) / s - 0.5 between scales (OpenCV's resize convention).
  auto full = [](const cv::Point2f& p, double scale) {
    const double inv = 1.0 / scale;
    return Eigen::Vector2d((p.x + 0.5) * inv - 0.5, (p.y + 0.5) * inv - 0.5);
  };
  for (std::size_t i = 0; i < lr.size(); ++i) {
    const int j = lr[i];
    if (j < 0 || rl[j] != static_cast<int>(i)) continue;  // mutual check
    out.left.push_back(full(l.keypoints[i].pt, l.scale));
    out.right.push_back(full(r.keypoints[j].pt, r.scale));
  }
  progress.step("features", 1.0);
  return out;
}

}  // namespace

FeatureMatches match_detected(const ImageFeatures& left, const ImageFeatures& right,
                              const ReconstructionPreset& preset) {
  NoProgress quiet;
  return match(left, right, preset, quiet);
}

FeatureMatches match_features(const cv::Mat& left, const cv::Mat& right,
                              const ReconstructionPreset& preset, Progress& progress) {
  progress.step("features: both images", 0.0);
  const double scale = working_scale(std::max(left.cols, right.cols), preset.feature_max_width);
  // SIFT leaves most of its time on one thread: up to the standard preset's
  // working width the right image is detected beside the left (1.2 s less
  // on a 24 Mpx pair at standard; a second tile's scale space, 270 MB more
  // for that time, 507 -> 779 MB for the pair alone). The precise preset's
  // pair is already near the tablet's 1.5 GB: one after the other there.
  ImageFeatures l, r;
  if (preset.feature_max_width <= kFeaturesSideBySideMaxWidth) {
    auto right_features =
        std::async(std::launch::async, [&] { return detect(right, scale, preset); });
    l = detect(left, scale, preset);
    r = right_features.get();
  } else {
    l = detect(left, scale, preset);
    r = detect(right, scale, preset);
  }
  progress.step("features: matched", 0.3);
  return match(l, r, preset, progress);
}

}  // namespace rockface::photogrammetry
