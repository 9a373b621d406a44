#include "core/photogrammetry/reconstruction/accuracy.h"

#include <cstdio>

namespace rockface::photogrammetry {

namespace {
std::string format(const char* fmt, double a, double b = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}
}  // namespace

AccuracyPrediction predict_accuracy(const AccuracyInputs& in, const AccuracyLimits& limits) {
  AccuracyPrediction out;
  if (in.base > 0 && in.focal_px > 0)
    out.sigma_z = in.distance * in.distance * in.disparity_sigma_px / (in.base * in.focal_px);
  out.base_ratio = in.distance > 0 ? in.base / in.distance : 0;
  if (out.base_ratio < limits.min_base_ratio)
    out.warnings.push_back(
        format("base/distance is 1/%.1f, narrower than 1/%.0f: depth precision "
               "suffers; move the stations further apart",
               1.0 / out.base_ratio, 1.0 / limits.min_base_ratio));
  else if (out.base_ratio > limits.max_base_ratio)
    out.warnings.push_back(
        format("base/distance is 1/%.1f, wider than 1/%.0f: the views differ "
               "much and dense matching loses surface; move the stations closer",
               1.0 / out.base_ratio, 1.0 / limits.max_base_ratio));
  if (in.inliers < limits.min_inliers)
    out.warnings.push_back(
        format("only %.0f tie points support the relative orientation (fewer "
               "than %.0f): it is poorly determined",
               in.inliers, limits.min_inliers));
  if (in.overlap < limits.min_overlap)
    out.warnings.push_back(
        format("low overlap: only %.0f %% of the left image has a matched "
               "surface (less than %.0f %%)",
               100 * in.overlap, 100 * limits.min_overlap));
  if (in.smallest_target_px && *in.smallest_target_px < limits.min_target_px)
    out.warnings.push_back(
        format("target too small: %.1f px across (under %.0f px); its centre "
               "and so the scale are unreliable; come closer or zoom in",
               *in.smallest_target_px, limits.min_target_px));
  return out;
}

}  // namespace rockface::photogrammetry
