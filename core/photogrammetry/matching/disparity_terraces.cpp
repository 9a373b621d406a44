#include "core/photogrammetry/matching/disparity_terraces.h"

#include <cmath>
#include <vector>

#include "core/common/error.h"

namespace rockface::photogrammetry {

namespace {

struct Tread {
  int from = 0, to = 0;  // pixels [from, to)
  double centre = 0, value = 0;
};

// The straight lines through the treads' centres, written over
// [first tread's centre, last tread's centre].
std::size_t flatten_staircase(float* d, std::ptrdiff_t stride, const std::vector<Tread>& treads,
                              std::size_t first, std::size_t last) {
  std::size_t changed = 0;
  for (std::size_t k = first; k < last; ++k) {
    const Tread &a = treads[k], &b = treads[k + 1];
    const int i0 = static_cast<int>(std::ceil(a.centre)),
              i1 = static_cast<int>(std::ceil(b.centre));
    for (int i = i0; i < i1; ++i) {
      const double t = (i - a.centre) / (b.centre - a.centre);
      const float v = static_cast<float>(a.value + t * (b.value - a.value));
      if (d[i * stride] != v) {
        d[i * stride] = v;
        ++changed;
      }
    }
  }
  return changed;
}

// One run of known values [from, to) of a line.
std::size_t smooth_run(float* d, std::ptrdiff_t stride, int from, int to, const TerraceSmoothing& s,
                       std::vector<Tread>& treads) {
  treads.clear();
  int start = from;
  for (int i = from + 1; i <= to; ++i) {
    if (i < to && std::abs(d[i * stride] - d[(i - 1) * stride]) < s.min_riser_px) continue;
    Tread t;
    t.from = start;
    t.to = i;
    t.centre = 0.5 * (start + i - 1);
    double sum = 0;
    for (int k = start; k < i; ++k) sum += d[k * stride];
    t.value = sum / (i - start);
    treads.push_back(t);
    start = i;
  }
  std::size_t changed = 0;
  // Staircases: maximal runs of short treads whose risers climb one way.
  std::size_t k = 0;
  while (k < treads.size()) {
    if (treads[k].to - treads[k].from > s.max_tread_px) {
      ++k;
      continue;
    }
    std::size_t m = k;
    int sign = 0;
    while (m + 1 < treads.size() && treads[m + 1].to - treads[m + 1].from <= s.max_tread_px) {
      const float rise = d[treads[m + 1].from * stride] - d[(treads[m + 1].from - 1) * stride];
      const int rs = rise > 0 ? 1 : -1;
      if (std::abs(rise) > s.max_riser_px || (sign != 0 && rs != sign)) break;
      sign = rs;
      ++m;
    }
    if (static_cast<int>(m - k + 1) >= s.min_treads)
      changed += flatten_staircase(d, stride, treads, k, m);
    k = m > k ? m : k + 1;
  }
  return changed;
}

std::size_t smooth_line(float* d, std::ptrdiff_t stride, int n, const TerraceSmoothing& s,
                        std::vector<Tread>& treads) {
  std::size_t changed = 0;
  int i = 0;
  while (i < n) {
    while (i < n && std::isnan(d[i * stride])) ++i;
    int j = i;
    while (j < n && !std::isnan(d[j * stride])) ++j;
    if (j > i) changed += smooth_run(d, stride, i, j, s, treads);
    i = j;
  }
  return changed;
}

}  // namespace

std::size_t smooth_disparity_terraces(cv::Mat& disparity, const TerraceSmoothing& smoothing) {
  if (disparity.type() != CV_32F) throw InputError("disparity map", "expected CV_32F");
  if (smoothing.max_tread_px <= 0 || disparity.empty()) return 0;
  CV_Assert(disparity.isContinuous());
  const int rows = disparity.rows, cols = disparity.cols;
  float* d = disparity.ptr<float>(0);
  std::vector<Tread> treads;
  std::size_t changed = 0;
  for (int y = 0; y < rows; ++y)
    changed += smooth_line(d + static_cast<std::ptrdiff_t>(y) * cols, 1, cols, smoothing, treads);
  for (int x = 0; x < cols; ++x) changed += smooth_line(d + x, cols, rows, smoothing, treads);
  return changed;
}

}  // namespace rockface::photogrammetry
