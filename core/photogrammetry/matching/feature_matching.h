#pragma once
// Sparse correspondences between two photographs: SIFT keypoints (OpenCV
// features2d), nearest-neighbour matching with Lowe's ratio test and a mutual
// (cross) check. Coordinates are returned in full-resolution pixels of the
// original (distorted) images.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/reconstruction/preset.h"

namespace rockface::photogrammetry {

struct FeatureMatches {
  std::vector<Eigen::Vector2d> left, right;  // pixel positions, one pair per match
  int keypoints_left = 0, keypoints_right = 0;
  std::size_t size() const { return left.size(); }
};

// Both images 8-bit, grey or BGR. The images are scaled by
// working_scale(width, preset.feature_max_width) before detection (bounds memory and time).
FeatureMatches match_features(const cv::Mat& left, const cv::Mat& right,
                              const ReconstructionPreset& preset, Progress& progress);

// The SIFT keypoints and descriptors of one photograph, detected once and
// matched against several others (multi-image registration) without
// detecting again. Keypoints are in the pixels of the image scaled by `scale`.
struct ImageFeatures {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  double scale = 1;
};

// Detects at `scale` (working_scale(width, preset.feature_max_width) for one
// image on its own); match_features detects both images at the scale of the
// wider one and then matches as match_detected does.
ImageFeatures detect_features(const cv::Mat& image, double scale,
                              const ReconstructionPreset& preset);
FeatureMatches match_detected(const ImageFeatures& left, const ImageFeatures& right,
                              const ReconstructionPreset& preset);

// 8-bit single-channel version of an 8-bit grey/BGR/BGRA image.
cv::Mat to_grey(const cv::Mat& image);

}  // namespace rockface::photogrammetry
