#include "core/photogrammetry/reconstruction/accuracy.h"

#include "core/common/number_format.h"

namespace rockface::photogrammetry {

AccuracyPrediction predict_accuracy(const AccuracyInputs& in, const AccuracyLimits& limits) {
  AccuracyPrediction out;
  if (in.base > 0 && in.focal_px > 0)
    out.sigma_z = in.distance * in.distance * in.disparity_sigma_px / (in.base * in.focal_px);
  out.base_ratio = in.distance > 0 ? in.base / in.distance : 0;
  if (out.base_ratio < limits.min_base_ratio)
    out.warnings.push_back("base/distance is 1/" + format_fixed(1.0 / out.base_ratio, 1) +
                           ", narrower than 1/" + format_fixed(1.0 / limits.min_base_ratio, 0) +
                           ": depth precision suffers; move the stations further apart");
  else if (out.base_ratio > limits.max_base_ratio)
    out.warnings.push_back(
        "base/distance is 1/" + format_fixed(1.0 / out.base_ratio, 1) + ", wider than 1/" +
        format_fixed(1.0 / limits.max_base_ratio, 0) +
        ": the views differ much and dense matching loses surface; move the stations closer");
  if (in.inliers < limits.min_inliers)
    out.warnings.push_back("only " + format_fixed(in.inliers, 0) +
                           " tie points support the relative orientation (fewer than " +
                           format_fixed(limits.min_inliers, 0) + "): it is poorly determined");
  if (in.overlap < limits.min_overlap)
    out.warnings.push_back("low overlap: only " + format_fixed(100 * in.overlap, 0, " %") +
                           " of the left image has a matched surface (less than " +
                           format_fixed(100 * limits.min_overlap, 0, " %") + ")");
  if (in.smallest_target_px && *in.smallest_target_px < limits.min_target_px)
    out.warnings.push_back("target too small: " + format_fixed(*in.smallest_target_px, 1, " px") +
                           " across (under " + format_fixed(limits.min_target_px, 0, " px") +
                           "); its centre and so the scale are unreliable; come closer or zoom in");
  return out;
}

}  // namespace rockface::photogrammetry
