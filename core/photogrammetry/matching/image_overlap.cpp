#include "core/photogrammetry/matching/image_overlap.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/photogrammetry/matching/feature_matching.h"

namespace rockface::photogrammetry {

Thumbnail make_thumbnail(const cv::Mat& photograph, int width) {
  Thumbnail t;
  const cv::Mat grey = to_grey(photograph);
  t.scale = static_cast<double>(width) / grey.cols;
  const int height = std::max(8, static_cast<int>(std::lround(grey.rows * t.scale)));
  cv::Mat small;
  cv::resize(grey, small, cv::Size(width, height), 0, 0, cv::INTER_AREA);
  small.convertTo(t.grey, CV_32F);
  t.grey -= cv::mean(t.grey)[0];
  return t;
}

namespace {

// 1 inside, a cosine taper over the outer 8 % of each side. A full Hanning
// window would weigh down the frame's edges, where two photographs that
// share a third of the frame have all they share.
cv::Mat edge_taper(cv::Size size) {
  auto ramp = [](int n) {
    std::vector<float> w(static_cast<std::size_t>(n), 1.0f);
    const int m = std::max(1, n * 8 / 100);
    for (int i = 0; i < m; ++i) {
      const float v = 0.5f * (1 - std::cos(static_cast<float>(CV_PI) * (i + 0.5f) / m));
      w[static_cast<std::size_t>(i)] = w[static_cast<std::size_t>(n - 1 - i)] = v;
    }
    return w;
  };
  const auto wx = ramp(size.width), wy = ramp(size.height);
  cv::Mat window(size, CV_32F);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      window.at<float>(y, x) = wx[static_cast<std::size_t>(x)] * wy[static_cast<std::size_t>(y)];
  return window;
}

}  // namespace

CoarseOverlap coarse_overlap(const Thumbnail& a, const Thumbnail& b) {
  CoarseOverlap o;
  if (a.grey.size() != b.grey.size()) return o;
  // The window keeps the thumbnails' edges from correlating as a shift of 0;
  // padding each to twice its size with zeros makes the correlation linear,
  // so that a shift of more than half the frame is not taken for one of
  // less the other way.
  const cv::Mat window = edge_taper(a.grey.size());
  auto padded = [&](const cv::Mat& g) {
    cv::Mat out;
    cv::copyMakeBorder(g.mul(window), out, 0, g.rows, 0, g.cols, cv::BORDER_CONSTANT, 0);
    return out;
  };
  const cv::Point2d shift =
      cv::phaseCorrelate(padded(a.grey), padded(b.grey), cv::noArray(), &o.response);
  o.shift_px = Eigen::Vector2d(shift.x, shift.y) / a.scale;
  const double w = a.grey.cols, h = a.grey.rows;
  o.fraction = std::max(0.0, 1 - std::abs(shift.x) / w) * std::max(0.0, 1 - std::abs(shift.y) / h);
  if (!std::isfinite(o.response)) o.response = 0;
  return o;
}

}  // namespace rockface::photogrammetry
