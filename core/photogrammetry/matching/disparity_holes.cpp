#include "core/photogrammetry/matching/disparity_holes.h"

#include <cmath>

#include "core/common/error.h"

namespace rockface::photogrammetry {

namespace {

// Fills the gaps of one line (a row, or a column read with a stride) into
// `sum` / `count`: the values each gap's linear interpolation gives.
void fill_line(const float* d, std::ptrdiff_t stride, int n, const DisparityHoleFill& fill,
               float* sum, unsigned char* count, std::ptrdiff_t out_stride) {
  int last_valid = -1;
  for (int i = 0; i < n; ++i) {
    const float v = d[i * stride];
    if (std::isnan(v)) continue;
    const int gap = i - last_valid - 1;
    if (last_valid >= 0 && gap > 0 && gap <= fill.max_gap_px) {
      const float a = d[last_valid * stride];
      if (std::abs(v - a) <= fill.max_slope_px * (gap + 1)) {
        for (int k = last_valid + 1; k < i; ++k) {
          const float t = static_cast<float>(k - last_valid) / static_cast<float>(gap + 1);
          sum[k * out_stride] += a + t * (v - a);
          ++count[k * out_stride];
        }
      }
    }
    last_valid = i;
  }
}

}  // namespace

std::size_t fill_disparity_holes(cv::Mat& disparity, const DisparityHoleFill& fill) {
  if (disparity.type() != CV_32F) throw InputError("disparity map", "expected CV_32F");
  if (fill.max_gap_px <= 0 || disparity.empty()) return 0;
  CV_Assert(disparity.isContinuous());
  const int rows = disparity.rows, cols = disparity.cols;
  cv::Mat sum = cv::Mat::zeros(disparity.size(), CV_32F);
  cv::Mat count = cv::Mat::zeros(disparity.size(), CV_8U);
  const float* d = disparity.ptr<float>(0);
  float* s = sum.ptr<float>(0);
  unsigned char* c = count.ptr<unsigned char>(0);
  for (int y = 0; y < rows; ++y) {
    const std::ptrdiff_t o = static_cast<std::ptrdiff_t>(y) * cols;
    fill_line(d + o, 1, cols, fill, s + o, c + o, 1);
  }
  for (int x = 0; x < cols; ++x) fill_line(d + x, cols, rows, fill, s + x, c + x, cols);
  std::size_t filled = 0;
  float* out = disparity.ptr<float>(0);
  for (std::size_t i = 0; i < disparity.total(); ++i)
    if (c[i] > 0) {
      out[i] = s[i] / static_cast<float>(c[i]);
      ++filled;
    }
  return filled;
}

}  // namespace rockface::photogrammetry
