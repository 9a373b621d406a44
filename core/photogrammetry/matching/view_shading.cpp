#include "core/photogrammetry/matching/view_shading.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "core/common/number_format.h"
#include "core/photogrammetry/matching/feature_matching.h"

namespace rockface::photogrammetry {

namespace {

// Local mean grey level (float), the Gaussian of sigma_px.
cv::Mat local_level(const cv::Mat& image, double sigma_px) {
  cv::Mat grey;
  to_grey(image).convertTo(grey, CV_32F);
  cv::Mat level;
  cv::GaussianBlur(grey, level, cv::Size(0, 0), sigma_px, 0, cv::BORDER_REFLECT);
  return level;
}

// Bilinear sample; nullopt-like NaN outside.
float sample(const cv::Mat& level, const Eigen::Vector2d& px) {
  const double x = px.x(), y = px.y();
  if (!(x >= 0 && y >= 0 && x <= level.cols - 1 && y <= level.rows - 1))
    return std::numeric_limits<float>::quiet_NaN();
  const int x0 = std::min(static_cast<int>(x), level.cols - 2 < 0 ? 0 : level.cols - 2);
  const int y0 = std::min(static_cast<int>(y), level.rows - 2 < 0 ? 0 : level.rows - 2);
  const double fx = x - x0, fy = y - y0;
  const int x1 = std::min(x0 + 1, level.cols - 1), y1 = std::min(y0 + 1, level.rows - 1);
  const double top = (1 - fx) * level.at<float>(y0, x0) + fx * level.at<float>(y0, x1);
  const double bottom = (1 - fx) * level.at<float>(y1, x0) + fx * level.at<float>(y1, x1);
  return static_cast<float>((1 - fy) * top + fy * bottom);
}

double quantile(std::vector<double> v, double q) {
  const auto k = static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

ViewShading compare_view_shading(const cv::Mat& left, const cv::Mat& right,
                                 const std::vector<Eigen::Vector2d>& left_px,
                                 const std::vector<Eigen::Vector2d>& right_px,
                                 const ViewShadingOptions& options) {
  ViewShading out;
  if (left.empty() || right.empty()) return out;
  const cv::Mat level_left = local_level(left, options.window_sigma_px);
  const cv::Mat level_right = local_level(right, options.window_sigma_px);
  std::vector<double> log_ratio;
  const std::size_t n = std::min(left_px.size(), right_px.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double a = sample(level_left, left_px[i]), b = sample(level_right, right_px[i]);
    if (!(a >= options.min_level_grey && b >= options.min_level_grey)) continue;  // NaN too
    if (a > options.max_level_grey || b > options.max_level_grey) continue;
    log_ratio.push_back(std::log(b / a));
  }
  if (static_cast<int>(log_ratio.size()) < options.min_samples) return out;
  out.samples = static_cast<int>(log_ratio.size());
  const double median = quantile(log_ratio, 0.5);
  const double lo = quantile(log_ratio, 0.1), hi = quantile(log_ratio, 0.9);
  out.gain = std::exp(median);
  out.spread = 0.5 * (hi - lo);
  out.lowest = std::exp(lo - median);
  out.highest = std::exp(hi - median);
  return out;
}

cv::Mat normalise_local_brightness(const cv::Mat& image, double sigma_px, double dark_grey) {
  cv::Mat value;
  image.convertTo(value, CV_32F);
  cv::Mat mean;
  cv::GaussianBlur(value, mean, cv::Size(0, 0), sigma_px, 0, cv::BORDER_REFLECT);
  mean = cv::max(mean, dark_grey);
  cv::Mat ratio;
  cv::divide(value, mean, ratio, 100.0);
  cv::Mat out;
  ratio.convertTo(out, image.depth());  // saturating, rounded
  return out;
}

std::string shading_warning(const ViewShading& s) {
  return "the two photographs light the face differently: the same rock is " +
         format_fixed(100 * (s.lowest - 1), 0) + " to +" + format_fixed(100 * (s.highest - 1), 0) +
         " % brighter in the right one than one exposure gain explains (" +
         std::to_string(s.samples) +
         " tie points), as a flash on the camera or strong vignetting does; dense matching "
         "follows such shading and tilts the surface, so it ran on brightness-normalised "
         "images. Better next time: light the face with lamps away from the cameras (or "
         "shoot both photographs with the flash at one position), not with the camera's flash";
}

}  // namespace rockface::photogrammetry
