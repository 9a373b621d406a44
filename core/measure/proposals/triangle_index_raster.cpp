#include "core/measure/proposals/triangle_index_raster.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <utility>

namespace rockface::measure::proposals {

void draw_triangle_index(cv::Mat& rows, int first_row, const cv::Point corners[3], int index) {
  const cv::Point a = corners[0];
  cv::Point b = corners[1], c = corners[2];
  const std::int64_t area = static_cast<std::int64_t>(b.x - a.x) * (c.y - a.y) -
                            static_cast<std::int64_t>(b.y - a.y) * (c.x - a.x);
  if (area == 0) return;
  if (area < 0) std::swap(b, c);
  constexpr int kOne = 1 << kRasterShift, kHalf = kOne / 2;
  // The pixels whose squares reach the triangle's bounding box.
  const auto first_pixel = [](int v) {
    return -((kHalf - v) >> kRasterShift);
  };                                                                          // ceil((v - h) / 1)
  const auto last_pixel = [](int v) { return (v + kHalf) >> kRasterShift; };  // floor((v + h) / 1)
  const int x0 = std::max(0, first_pixel(std::min({a.x, b.x, c.x})));
  const int x1 = std::min(rows.cols - 1, last_pixel(std::max({a.x, b.x, c.x})));
  const int y0 = std::max(first_row, first_pixel(std::min({a.y, b.y, c.y})));
  const int y1 = std::min(first_row + rows.rows - 1, last_pixel(std::max({a.y, b.y, c.y})));
  if (x0 > x1 || y0 > y1) return;
  // Edge functions at the first centre, raised by the most they grow over
  // half a pixel each way (the square's corner farthest into the
  // triangle), and their steps per pixel: a square reaches the triangle
  // when none of them is negative there.
  struct Edge {
    std::int64_t at, step_x, step_y;
  };
  const auto edge = [&](const cv::Point& p, const cv::Point& q) {
    const std::int64_t dx = q.x - p.x, dy = q.y - p.y;
    const std::int64_t px = static_cast<std::int64_t>(x0) * kOne - p.x;
    const std::int64_t py = static_cast<std::int64_t>(y0) * kOne - p.y;
    const std::int64_t reach = kHalf * (std::abs(dx) + std::abs(dy));
    return Edge{dx * py - dy * px + reach, -dy * kOne, dx * kOne};
  };
  Edge e[3] = {edge(a, b), edge(b, c), edge(c, a)};
  for (int y = y0; y <= y1; ++y) {
    int* out = rows.ptr<int>(y - first_row);
    std::int64_t w0 = e[0].at, w1 = e[1].at, w2 = e[2].at;
    for (int x = x0; x <= x1; ++x) {
      if ((w0 | w1 | w2) >= 0) out[x] = index;
      w0 += e[0].step_x;
      w1 += e[1].step_x;
      w2 += e[2].step_x;
    }
    for (auto& k : e) k.at += k.step_y;
  }
}

}  // namespace rockface::measure::proposals
