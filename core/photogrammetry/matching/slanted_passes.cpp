#include "core/photogrammetry/matching/slanted_passes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "core/common/error.h"

namespace rockface::photogrammetry {

namespace {

struct Frame {
  double xc = 0, yc = 0;
};

Frame centre_of(const cv::Size& size) {
  return {(size.width - 1) / 2.0, (size.height - 1) / 2.0};
}

// x_right of a warped column x' (the warp's definition, slanted_passes.h).
double right_column(const Frame& f, const DisparitySlope& s, double x_warped, double y) {
  return f.xc + (1 - s.along_row) * (x_warped - f.xc) - s.along_column * (y - f.yc);
}

// The local slope of `d` at (x, y) from the disparities `k` pixels either
// side along the row and the column; false where one of them is unknown.
bool local_slope(const cv::Mat& d, int x, int y, int k, double& sx, double& sy) {
  if (x < k || y < k || x + k >= d.cols || y + k >= d.rows) return false;
  const float l = d.at<float>(y, x - k), r = d.at<float>(y, x + k);
  const float u = d.at<float>(y - k, x), b = d.at<float>(y + k, x);
  if (std::isnan(l) || std::isnan(r) || std::isnan(u) || std::isnan(b)) return false;
  sx = (r - l) / (2.0 * k);
  sy = (b - u) / (2.0 * k);
  return true;
}

// The search range of a pass: the first pass's disparities, taken into the
// warped frame, where the first pass's own slope is near the pass's (1st to
// 99th percentile, widened by a margin), capped around their median.
bool pass_range(const cv::Mat& first, const DisparitySlope& s, const SlantedPassOptions& o,
                SlantedRange& out) {
  const Frame f = centre_of(first.size());
  const int k = o.slope_step_px;
  std::vector<double> d;
  for (int y = k; y + k < first.rows; ++y)
    for (int x = k; x + k < first.cols; ++x) {
      const float v = first.at<float>(y, x);
      double sx = 0, sy = 0;
      if (std::isnan(v) || !local_slope(first, x, y, k, sx, sy)) continue;
      if (std::abs(sx - s.along_row) > o.slope_tolerance ||
          std::abs(sy - s.along_column) > o.slope_tolerance)
        continue;
      // x_warped of the right image's column x - v (the inverse of right_column).
      const double xw = f.xc + (x - v - f.xc + s.along_column * (y - f.yc)) / (1 - s.along_row);
      d.push_back(x - xw);
    }
  if (static_cast<double>(d.size()) < o.min_fraction * static_cast<double>(first.total()))
    return false;
  std::sort(d.begin(), d.end());
  // A margin of 16 px: the first pass's terraces stand a few pixels off the
  // slope, and its cap may have cut the surface's far end.
  const double margin = 16;
  const double lo = d[d.size() / 100] - margin, hi = d[d.size() - 1 - d.size() / 100] + margin;
  int min_d = static_cast<int>(std::floor(lo));
  int num = (static_cast<int>(std::ceil(hi)) - min_d + 15) / 16 * 16;
  const int cap = std::max(16, o.max_disparities / 16 * 16);
  if (num > cap) {
    num = cap;
    min_d = static_cast<int>(std::lround(d[d.size() / 2])) - num / 2;
  }
  out = {min_d, num};
  return true;
}

}  // namespace

cv::Mat warp_for_slope(const cv::Mat& right, const DisparitySlope& slope) {
  const Frame f = centre_of(right.size());
  cv::Mat mx(right.size(), CV_32F), my(right.size(), CV_32F);
  for (int y = 0; y < right.rows; ++y) {
    float* px = mx.ptr<float>(y);
    float* py = my.ptr<float>(y);
    for (int x = 0; x < right.cols; ++x) {
      px[x] = static_cast<float>(right_column(f, slope, x, y));
      py[x] = static_cast<float>(y);
    }
  }
  cv::Mat out;
  cv::remap(right, out, mx, my, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  return out;
}

SlantedResult match_slanted(const cv::Mat& right, const cv::Mat& first,
                            const SlantedPassOptions& options, const PassMatcher& matcher) {
  if (first.type() != CV_32F || first.size() != right.size())
    throw InputError("disparity map", "expected CV_32F of the right image's size");
  for (const auto& s : options.slopes)
    if (!(s.along_row < 0.95))
      throw InputError("slanted passes", "a slope along the row must be below 0.95 px per px");
  const Frame f = centre_of(first.size());
  std::vector<cv::Mat> candidates;  // in the real pair
  std::vector<DisparitySlope> slopes;
  SlantedResult out;
  for (const auto& s : options.slopes) {
    SlantedRange range;
    if (!pass_range(first, s, options, range)) continue;
    const cv::Mat warped = matcher(warp_for_slope(right, s), range);
    cv::Mat back(first.size(), CV_32F);
    for (int y = 0; y < back.rows; ++y) {
      const float* w = warped.ptr<float>(y);
      float* b = back.ptr<float>(y);
      for (int x = 0; x < back.cols; ++x)
        b[x] = std::isnan(w[x]) ? w[x] : static_cast<float>(x - right_column(f, s, x - w[x], y));
    }
    candidates.push_back(std::move(back));
    slopes.push_back(s);
    ++out.passes_run;
  }
  out.disparity = first.clone();
  if (candidates.empty()) return out;
  const int k = options.slope_step_px;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // What the first pass sees in the right image: per right pixel the
  // largest (nearest) disparity that maps onto it. A candidate whose right
  // pixel a nearer measured surface covers would be seen through it: an
  // occluded pixel, not a match.
  cv::Mat claimed(first.size(), CV_32F, cv::Scalar(-1e9f));
  for (int y = 0; y < first.rows; ++y)
    for (int x = 0; x < first.cols; ++x) {
      const float v = first.at<float>(y, x);
      if (std::isnan(v)) continue;
      const int xr = static_cast<int>(std::lround(x - v));
      if (xr < 0 || xr >= first.cols) continue;
      float& c = claimed.at<float>(y, xr);
      c = std::max(c, v);
    }
  for (int y = 0; y < first.rows; ++y)
    for (int x = 0; x < first.cols; ++x) {
      // Flatness in each pass's own frame: its map's slope less the pass's.
      // A candidate whose neighbours are unknown ranks after every candidate
      // with a measured slope.
      double best = std::numeric_limits<double>::infinity();
      float pick = nan;
      bool slanted = false;
      auto consider = [&](const cv::Mat& d, const DisparitySlope& s, double bias, bool is_slanted) {
        const float v = d.at<float>(y, x);
        if (std::isnan(v)) return;
        double sx = 0, sy = 0;
        const double score = local_slope(d, x, y, k, sx, sy)
                                 ? std::hypot(sx - s.along_row, sy - s.along_column) + bias
                                 : 1e6 + bias;
        if (score < best) {
          best = score;
          pick = v;
          slanted = is_slanted;
        }
      };
      consider(first, {}, options.first_pass_bias, false);
      const float known = first.at<float>(y, x);
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        // Where the first pass measured, a slanted pass may only move it
        // onto its slope (terraces), not to another surface.
        const float v = candidates[c].at<float>(y, x);
        if (!std::isnan(known) && !(std::abs(v - known) <= options.max_change_px)) continue;
        if (!std::isnan(v)) {
          const int xr = static_cast<int>(std::lround(x - v));
          if (xr >= 0 && xr < first.cols && claimed.at<float>(y, xr) > v + options.occlusion_px)
            continue;
        }
        consider(candidates[c], slopes[c], 0.0, true);
      }
      out.disparity.at<float>(y, x) = pick;
      if (slanted) ++out.slanted;
    }
  return out;
}

}  // namespace rockface::photogrammetry
