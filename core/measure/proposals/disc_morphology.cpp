#include "core/measure/proposals/disc_morphology.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace rockface::measure::proposals {

namespace {

cv::Mat disc(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
}

// The half-width of the element's run in each of its rows (from -radius to
// +radius); empty when a row is not one centred run (then OpenCV decides).
std::vector<int> run_half_widths(int radius) {
  const cv::Mat element = disc(radius);
  std::vector<int> half;
  for (int ky = 0; ky < element.rows; ++ky) {
    const std::uint8_t* row = element.ptr<std::uint8_t>(ky);
    int first = -1, last = -1;
    for (int kx = 0; kx < element.cols; ++kx)
      if (row[kx]) {
        if (last >= 0 && last != kx - 1) return {};  // two runs
        if (first < 0) first = kx;
        last = kx;
      }
    if (first < 0 || radius - first != last - radius) return {};  // empty or off centre
    half.push_back(radius - first);
  }
  return half;
}

// The one value of the set pixels of an 8-bit image (0 when none is set);
// -1 when they hold more than one.
int mask_value(const cv::Mat& image) {
  int value = 0;
  for (int r = 0; r < image.rows; ++r) {
    const std::uint8_t* p = image.ptr<std::uint8_t>(r);
    for (int c = 0; c < image.cols; ++c)
      if (p[c] && p[c] != value) {
        if (value) return -1;
        value = p[c];
      }
  }
  return value;
}

// Every run of pixels equal to (`equal`) or other than `value` in each row,
// spread by the element's rows into `out`, whose spans are set to `fill`.
void spread_runs(const cv::Mat& image, std::uint8_t value, bool equal, const std::vector<int>& half,
                 cv::Mat& out, std::uint8_t fill) {
  const int w = image.cols, h = image.rows, radius = static_cast<int>(half.size() / 2);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* p = image.ptr<std::uint8_t>(y);
    for (int x = 0; x < w;) {
      if ((p[x] == value) != equal) {
        ++x;
        continue;
      }
      const int from = x;
      while (x < w && (p[x] == value) == equal) ++x;
      for (int ky = 0; ky < static_cast<int>(half.size()); ++ky) {
        const int row = y + ky - radius;
        if (row < 0 || row >= h) continue;
        const int x0 = std::max(0, from - half[ky]), x1 = std::min(w - 1, x - 1 + half[ky]);
        std::memset(out.ptr<std::uint8_t>(row) + x0, fill, static_cast<std::size_t>(x1 - x0 + 1));
      }
    }
  }
}

// Each value above 0 spread over its element into `out` (all 0), the
// largest kept.
void spread_values(const cv::Mat& image, const std::vector<int>& half, cv::Mat& out) {
  const int w = image.cols, h = image.rows, radius = static_cast<int>(half.size() / 2);
  for (int y = 0; y < h; ++y) {
    const float* p = image.ptr<float>(y);
    for (int x = 0; x < w; ++x) {
      const float v = p[x];
      if (!(v > 0)) continue;
      for (int ky = 0; ky < static_cast<int>(half.size()); ++ky) {
        const int row = y + ky - radius;
        if (row < 0 || row >= h) continue;
        float* o = out.ptr<float>(row);
        const int x0 = std::max(0, x - half[ky]), x1 = std::min(w - 1, x + half[ky]);
        for (int c = x0; c <= x1; ++c) o[c] = std::max(o[c], v);
      }
    }
  }
}

}  // namespace

cv::Mat dilate_disc(const cv::Mat& image, int radius) {
  const std::vector<int> half = radius > 0 ? run_half_widths(radius) : std::vector<int>{};
  if (!half.empty() && image.type() == CV_8UC1) {
    const int value = mask_value(image);
    if (value >= 0) {
      // Beyond the image nothing counts: the runs' spans are clipped.
      cv::Mat out(image.size(), CV_8U, cv::Scalar(0));
      if (value > 0)
        spread_runs(image, static_cast<std::uint8_t>(value), true, half, out,
                    static_cast<std::uint8_t>(value));
      return out;
    }
  }
  if (!half.empty() && image.type() == CV_32FC1) {
    double least = 0;
    cv::minMaxLoc(image, &least);
    if (least >= 0 && cv::checkRange(image)) {
      // Every value is at least 0: the extreme over an element is the
      // largest value spread into it, or 0.
      cv::Mat out(image.size(), CV_32F, cv::Scalar(0));
      spread_values(image, half, out);
      return out;
    }
  }
  cv::Mat out;
  cv::dilate(image, out, disc(std::max(radius, 0)));
  return out;
}

cv::Mat erode_disc(const cv::Mat& image, int radius) {
  const std::vector<int> half = radius > 0 ? run_half_widths(radius) : std::vector<int>{};
  if (!half.empty() && image.type() == CV_8UC1) {
    const int value = mask_value(image);
    if (value > 0) {
      // Each unset pixel clears its element; beyond the image nothing
      // counts (a border of set pixels).
      cv::Mat out(image.size(), CV_8U, cv::Scalar(value));
      spread_runs(image, static_cast<std::uint8_t>(value), false, half, out, 0);
      return out;
    }
    if (value == 0) return cv::Mat::zeros(image.size(), CV_8U);
  }
  cv::Mat out;
  cv::erode(image, out, disc(std::max(radius, 0)));
  return out;
}

}  // namespace rockface::measure::proposals
