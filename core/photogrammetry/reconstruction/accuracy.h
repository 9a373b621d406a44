#pragma once
// What a reconstruction can be trusted for: the predicted depth precision
// of a normal-case stereo pair, sigma_Z = Z^2 sigma_d / (B f), and warnings
// about the capture (geometry, overlap, tie points, target size).
#include <optional>
#include <string>
#include <vector>

namespace rockface::photogrammetry {

struct AccuracyLimits {
  double min_base_ratio = 1.0 / 8;  // base / distance; narrower: depth precision suffers
  double max_base_ratio = 1.0 / 5;  // wider: the views differ too much for dense matching
  int min_inliers = 200;            // fewer tie points: orientation poorly determined
  double min_overlap = 0.5;         // fraction of the left image with a matched surface
  double min_target_px = 8.0;       // target diameter; smaller: centre not reliable
};

struct AccuracyInputs {
  double distance = 0;            // median depth along the left optical axis (model/world units)
  double base = 0;                // same units
  double focal_px = 0;            // at the scale the disparities were measured
  double disparity_sigma_px = 0;  // at that scale
  int inliers = 0;
  double overlap = 0;  // fraction, see AccuracyLimits::min_overlap
  std::optional<double> smallest_target_px;
};

struct AccuracyPrediction {
  double sigma_z = 0;     // predicted depth precision, same units as distance
  double base_ratio = 0;  // base / distance
  std::vector<std::string> warnings;
};

AccuracyPrediction predict_accuracy(const AccuracyInputs& in, const AccuracyLimits& limits = {});

}  // namespace rockface::photogrammetry
