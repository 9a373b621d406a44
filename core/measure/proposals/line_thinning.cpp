#include "core/measure/proposals/line_thinning.h"

#include <cstdint>
#include <vector>

namespace rockface::measure::proposals {

namespace {

// Whether the pixel at `i` (an interior pixel of a 0 / 1 image of row
// length `w`) is removed in sub-iteration `second`: one 0 -> 1 transition
// around it, two to six set neighbours, and the sub-iteration's two
// products of neighbours zero (Zhang & Suen 1984).
bool removable(const std::uint8_t* p, std::ptrdiff_t i, std::ptrdiff_t w, bool second) {
  // Clockwise from north: p2 (N), p3 (NE), p4 (E), p5 (SE), p6 (S),
  // p7 (SW), p8 (W), p9 (NW).
  const int n[8] = {p[i - w], p[i - w + 1], p[i + 1], p[i + w + 1],
                    p[i + w], p[i + w - 1], p[i - 1], p[i - w - 1]};
  int set = 0, rises = 0;
  for (int k = 0; k < 8; ++k) {
    set += n[k];
    rises += n[k] == 0 && n[(k + 1) % 8] == 1;
  }
  if (rises != 1 || set < 2 || set > 6) return false;
  const int p2 = n[0], p4 = n[2], p6 = n[4], p8 = n[6];
  return second ? p2 * p4 * p8 == 0 && p2 * p6 * p8 == 0 : p2 * p4 * p6 == 0 && p4 * p6 * p8 == 0;
}

}  // namespace

cv::Mat zhang_suen_thinning(const cv::Mat& binary) {
  CV_Assert(binary.type() == CV_8UC1);
  cv::Mat img(binary.size(), CV_8U);  // 0 / 1, continuous
  const int w = binary.cols, h = binary.rows;
  // The pixels that may be removed: set, not on the outermost rows and
  // columns (whose neighbourhoods are not whole).
  std::vector<std::ptrdiff_t> live;
  for (int r = 0; r < h; ++r) {
    const std::uint8_t* in = binary.ptr<std::uint8_t>(r);
    std::uint8_t* out = img.ptr<std::uint8_t>(r);
    for (int c = 0; c < w; ++c) {
      out[c] = in[c] != 0;
      if (out[c] && r > 0 && c > 0 && r + 1 < h && c + 1 < w)
        live.push_back(static_cast<std::ptrdiff_t>(r) * w + c);
    }
  }
  std::uint8_t* p = img.ptr<std::uint8_t>(0);
  std::vector<std::ptrdiff_t> removed;
  for (bool moved = true; moved;) {
    moved = false;
    for (const bool second : {false, true}) {
      // Decided on the image as it stands, then applied together.
      removed.clear();
      std::size_t kept = 0;
      for (const std::ptrdiff_t i : live) {
        if (removable(p, i, w, second))
          removed.push_back(i);
        else
          live[kept++] = i;
      }
      live.resize(kept);
      for (const std::ptrdiff_t i : removed) p[i] = 0;
      moved = moved || !removed.empty();
    }
  }
  return img * 255;
}

}  // namespace rockface::measure::proposals
