#include "core/photogrammetry/matching/image_contrast.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/photogrammetry/matching/feature_matching.h"

namespace rockface::photogrammetry {

namespace {

constexpr int kWorkingWidth = 1000;  // the fast preset's dense matching width
constexpr double kFineSigma = 1.0, kCoarseSigma = 4.0;
constexpr int kWindow = 15;

}  // namespace

cv::Mat band_pass(const cv::Mat& f) {
  cv::Mat fine, coarse;
  cv::GaussianBlur(f, fine, cv::Size(0, 0), kFineSigma, 0, cv::BORDER_REFLECT);
  cv::GaussianBlur(f, coarse, cv::Size(0, 0), kCoarseSigma, 0, cv::BORDER_REFLECT);
  return fine - coarse;
}

double band_pass_noise_gain() {
  cv::Mat delta = cv::Mat::zeros(61, 61, CV_32F);
  delta.at<float>(30, 30) = 1;
  const cv::Mat k = band_pass(delta);
  return cv::sum(k.mul(k))[0];
}

double sensor_noise_grey(const cv::Mat& f) {
  // Immerkaer (1996): the mask [1 -2 1; -2 4 -2; 1 -2 1] cancels smooth
  // image structure; the mean absolute response of Gaussian noise is
  // sigma * 6 sqrt(2 / pi)... (sum of squares of the mask is 36).
  cv::Mat lap;
  const cv::Matx33f mask(1, -2, 1, -2, 4, -2, 1, -2, 1);
  cv::filter2D(f, lap, CV_32F, mask, cv::Point(-1, -1), 0, cv::BORDER_REFLECT);
  std::vector<float> abs_lap;
  abs_lap.reserve(lap.total());
  for (int y = 1; y + 1 < lap.rows; ++y) {
    const float* row = lap.ptr<float>(y);
    for (int x = 1; x + 1 < lap.cols; ++x) abs_lap.push_back(std::abs(row[x]));
  }
  // The median, not the mean: rock edges and joint traces give large
  // responses; for Gaussian noise the median |response| is 0.6745 * 6 sigma.
  auto mid = abs_lap.begin() + static_cast<std::ptrdiff_t>(abs_lap.size() / 2);
  std::nth_element(abs_lap.begin(), mid, abs_lap.end());
  return abs_lap.empty() ? 0.0 : *mid / (0.6745 * 6.0);
}

ImageContrast measure_contrast(const cv::Mat& image) {
  cv::Mat grey = to_grey(image);
  if (grey.cols > kWorkingWidth) {
    const double s = static_cast<double>(kWorkingWidth) / grey.cols;
    cv::resize(grey, grey, cv::Size(), s, s, cv::INTER_AREA);
  }
  cv::Mat f;
  grey.convertTo(f, CV_32F);
  ImageContrast out;
  out.noise_grey = sensor_noise_grey(f);

  std::vector<uchar> levels(grey.begin<uchar>(), grey.end<uchar>());
  auto p90 =
      levels.begin() + static_cast<std::ptrdiff_t>(0.9 * static_cast<double>(levels.size() - 1));
  std::nth_element(levels.begin(), p90, levels.end());
  out.bright_grey = *p90;
  double lo = 0, hi = 0;
  cv::minMaxLoc(grey, &lo, &hi);
  out.darkest_grey = lo;
  out.brightest_grey = hi;
  auto p50 = levels.begin() + static_cast<std::ptrdiff_t>(levels.size() / 2);
  std::nth_element(levels.begin(), p50, levels.end());
  out.median_grey = *p50;

  const cv::Mat band = band_pass(f);
  cv::Mat energy;
  cv::boxFilter(band.mul(band), energy, CV_32F, cv::Size(kWindow, kWindow), cv::Point(-1, -1), true,
                cv::BORDER_REFLECT);
  std::vector<float> e(energy.begin<float>(), energy.end<float>());
  auto q = e.begin() + static_cast<std::ptrdiff_t>(0.75 * static_cast<double>(e.size() - 1));
  std::nth_element(e.begin(), q, e.end());
  const double noise_share = band_pass_noise_gain() * out.noise_grey * out.noise_grey;
  out.texture_grey = std::sqrt(std::max(0.0, static_cast<double>(*q) - noise_share));
  return out;
}

void require_matchable_contrast(const cv::Mat& image, const std::string& which) {
  const ImageContrast c = measure_contrast(image);
  // Grey levels to two decimals.
  const auto grey = [](double v) { return format_fixed(v, 2); };
  std::ostringstream s;
  if (c.darkest_grey + kBlankRange >= c.brightest_grey) {
    s << "the image is blank, black or uniform (grey levels " << grey(c.darkest_grey) << " to "
      << grey(c.brightest_grey)
      << "): nothing to match; the lens cap on, the shot taken in the dark, or a failed capture";
    throw InputError(which, s.str());
  }
  if (c.texture_grey < kMinMatchableTexture && c.median_grey >= kClippedImage) {
    s << "over-exposed: half the photograph is at " << grey(c.median_grey)
      << " grey levels or brighter, where the rock's texture is clipped (" << grey(c.texture_grey)
      << " grey levels rms left, at least " << grey(kMinMatchableTexture)
      << " needed): less flash or lamp on the face, or a shorter exposure";
    throw InputError(which, s.str());
  }
  if (c.texture_grey < kMinMatchableTexture && c.bright_grey < kDarkImage) {
    s << "under-exposed: the photograph is dark (nine pixels in ten below " << grey(c.bright_grey)
      << " grey levels) and the face's texture only " << grey(c.texture_grey)
      << " grey levels rms, at least " << grey(kMinMatchableTexture)
      << " needed: light the face (flash, lamps) or expose longer";
    throw InputError(which, s.str());
  }
  if (c.texture_grey < kMinMatchableTexture) {
    s << "dust haze: the face's contrast is too low for matching: its texture is "
      << grey(c.texture_grey) << " grey levels rms (sensor noise " << grey(c.noise_grey)
      << " taken out), at least " << grey(kMinMatchableTexture)
      << " needed; dust or fog between the camera and the face, too little light on it, or a "
         "fogged lens: wait for the dust to settle or ventilate, light the face, or come closer";
    throw InputError(which, s.str());
  }
  if (c.texture_grey < kMinTextureToNoise * c.noise_grey) {
    s << "sensor noise: the noise (" << grey(c.noise_grey)
      << " grey levels rms per pixel) outweighs "
      << "the face's texture (" << grey(c.texture_grey) << " grey levels rms), a ratio of "
      << grey(c.texture_grey / c.noise_grey) << " where at least " << grey(kMinTextureToNoise)
      << " is needed; a lower ISO with a longer exposure on a tripod, or more light on the face";
    throw InputError(which, s.str());
  }
}

}  // namespace rockface::photogrammetry
