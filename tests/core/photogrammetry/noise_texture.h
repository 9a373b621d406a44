#pragma once
// A rock-like grey texture for photogrammetry tests: uniform noise blurred at
// a fine and a coarse scale, mixed 0.6 / 0.4 and stretched to 0..255.
// Deterministic for a seed.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace rockface::test {

inline cv::Mat noise_texture(int width, int height, int seed, double fine_sigma,
                             double coarse_sigma) {
  cv::Mat a(height, width, CV_8UC1), b(height, width, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(a, cv::RNG::UNIFORM, 0, 256);
  rng.fill(b, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(a, a, cv::Size(0, 0), fine_sigma);
  cv::GaussianBlur(b, b, cv::Size(0, 0), coarse_sigma);
  cv::Mat t;
  cv::addWeighted(a, 0.6, b, 0.4, 0, t);
  cv::normalize(t, t, 0, 255, cv::NORM_MINMAX);
  return t;
}

}  // namespace rockface::test
