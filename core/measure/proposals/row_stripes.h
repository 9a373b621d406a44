#pragma once
// The cues' image work over stripes of rows on the analysis threads
// (issue 45: the tablet's first proposals within 2 s on its 2 cores).
// Every value is the one the whole image gives in one call: OpenCV's
// filters read a row view's neighbouring rows from the image it is cut
// from (their border rule applies only at the image's own edges), and
// per-pixel work writes only its own stripe's rows. The stripes run on
// OpenCV's own thread pool (cv::parallel_for_), the one its functions use
// inside: threads started for each stripe of each stage, beside that
// pool's, cost more CPU than they saved. ROCKFACE_THREADS=1
// (core/common/parallel.h) runs the one stripe on the calling thread.
//
// OpenCV's element-wise functions treat a continuous image as one array
// and run it in vectors of up to 16 floats, the last few elements on
// their own: stripes start at an element that is a multiple of 64 from
// the image's start, so each element is worked out the same way as in
// the whole image's one call.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include <opencv2/core.hpp>

#include "core/common/parallel.h"

namespace rockface::measure::proposals {

// The stripes' first rows for an image of `size`, one stripe per thread
// (fewer for a short image): multiples of the rows that make 64 elements.
inline std::vector<int> row_stripe_starts(cv::Size size, unsigned threads) {
  const int step = 64 / std::gcd(std::max(size.width, 1), 64);
  const int whole_steps = size.height / step;
  const int stripes = static_cast<int>(
      std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(whole_steps))));
  std::vector<int> starts;
  for (int k = 0; k < stripes; ++k) starts.push_back(whole_steps * k / stripes * step);
  return starts;
}

// f(cv::Range rows) for stripes covering the rows of an image of `size`.
// f must write only the rows of its stripe and read only what no stripe
// writes.
template <class F>
void for_row_stripes(cv::Size size, F&& f) {
  if (size.height <= 0) return;
  const unsigned threads =
      std::min(analysis_threads(), static_cast<unsigned>(std::max(1, cv::getNumThreads())));
  const std::vector<int> starts = row_stripe_starts(size, threads);
  const auto stripe = [&](int i) {
    const auto k = static_cast<std::size_t>(i);
    f(cv::Range(starts[k], k + 1 < starts.size() ? starts[k + 1] : size.height));
  };
  if (starts.size() == 1) {
    stripe(0);
    return;
  }
  const int count = static_cast<int>(starts.size());
  cv::parallel_for_(
      cv::Range(0, count),
      [&](const cv::Range& r) {
        for (int i = r.start; i < r.end; ++i) stripe(i);
      },
      count);
}

}  // namespace rockface::measure::proposals
