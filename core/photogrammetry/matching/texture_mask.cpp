#include "core/photogrammetry/matching/texture_mask.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/matching/image_contrast.h"

namespace rockface::photogrammetry {

namespace {

// The sensor's noise (rms grey levels) measured where the image is
// flattest: Immerkaer's estimator (the median of its mask's responses,
// image_contrast.h) over the tenth of the pixels whose windows vary least.
// Over the whole frame the median falls on texture when rock fills it (the
// Middlebury stones: the limit then took 15 % of their textured pixels);
// where the frame holds a dark background, its flattest tenth is that
// background's noise.
double noise_where_flattest(const cv::Mat& f, const cv::Mat& variance) {
  std::vector<float> v(variance.begin<float>(), variance.end<float>());
  if (v.empty()) return 0;
  auto tenth = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 10);
  std::nth_element(v.begin(), tenth, v.end());
  const float flat = *tenth;
  cv::Mat lap;
  const cv::Matx33f mask(1, -2, 1, -2, 4, -2, 1, -2, 1);
  cv::filter2D(f, lap, CV_32F, mask, cv::Point(-1, -1), 0, cv::BORDER_REFLECT);
  std::vector<float> response;
  for (int y = 1; y + 1 < f.rows; ++y) {
    const float* l = lap.ptr<float>(y);
    const float* e = variance.ptr<float>(y);
    for (int x = 1; x + 1 < f.cols; ++x)
      if (e[x] <= flat) response.push_back(std::abs(l[x]));
  }
  if (response.empty()) return 0;
  auto mid = response.begin() + static_cast<std::ptrdiff_t>(response.size() / 2);
  std::nth_element(response.begin(), mid, response.end());
  // For Gaussian noise the median |response| is 0.6745 x 6 sigma.
  return *mid / (0.6745 * 6.0);
}

}  // namespace

cv::Mat textured_pixels(const cv::Mat& image, const TextureCheck& check) {
  cv::Mat f;
  to_grey(image).convertTo(f, CV_32F);
  cv::Mat out(f.size(), CV_8U, cv::Scalar(255));
  if (!(check.min_texture_to_noise > 0)) return out;
  // The grey levels' variance over the window, against what the sensor's
  // noise alone gives: noise variance x (1 + ratio^2) is a window whose
  // texture, noise taken out, is `ratio` times the noise (amplitudes). The
  // raw variance, not a band of wavelengths, so that a window beside the
  // face's edge (rock in the window's reach, not in the window) holds noise
  // only: a band-pass spreads the edge's contrast over its own reach.
  const int w = std::max(1, check.window_px | 1);
  cv::Mat mean, mean_sq;
  cv::boxFilter(f, mean, CV_32F, cv::Size(w, w), cv::Point(-1, -1), true, cv::BORDER_REFLECT);
  cv::boxFilter(f.mul(f), mean_sq, CV_32F, cv::Size(w, w), cv::Point(-1, -1), true,
                cv::BORDER_REFLECT);
  const cv::Mat energy = mean_sq - mean.mul(mean);
  const double noise = noise_where_flattest(f, energy);
  const double r = check.min_texture_to_noise;
  const float limit = static_cast<float>(noise * noise * (1 + r * r));
  for (int y = 0; y < f.rows; ++y) {
    const float* e = energy.ptr<float>(y);
    std::uint8_t* o = out.ptr<std::uint8_t>(y);
    for (int x = 0; x < f.cols; ++x)
      if (!(e[x] > limit)) o[x] = 0;
  }
  return out;
}

std::size_t remove_untextured(cv::Mat& disparity, short invalid, const cv::Mat& textured) {
  std::size_t removed = 0;
  for (int y = 0; y < disparity.rows; ++y) {
    short* d = disparity.ptr<short>(y);
    const std::uint8_t* t = textured.ptr<std::uint8_t>(y);
    for (int x = 0; x < disparity.cols; ++x)
      if (!t[x] && d[x] > invalid) {
        d[x] = invalid;
        ++removed;
      }
  }
  return removed;
}

}  // namespace rockface::photogrammetry
