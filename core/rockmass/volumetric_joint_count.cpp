#include "core/rockmass/volumetric_joint_count.h"

#include <algorithm>
#include <cmath>

namespace rockface::rockmass {

VolumetricJointCount volumetric_joint_count(const std::vector<SetSpacing>& spacings,
                                            int random_traces, double area) {
  VolumetricJointCount out;
  out.random_traces = random_traces;
  out.window_area_m2 = area;
  for (const auto& s : spacings) {
    if (s.mean_m && *s.mean_m > 0) {
      out.from_sets += 1.0 / *s.mean_m;
      ++out.sets_used;
    } else {
      out.sets_without_spacing.push_back(s.label);
    }
  }
  if (random_traces > 0 && area > 0) out.from_random = random_traces / (5.0 * std::sqrt(area));
  if (out.sets_used > 0) {
    out.jv = out.from_sets + out.from_random;
    out.rqd_palmstrom = std::clamp(110.0 - 2.5 * *out.jv, 0.0, 100.0);
  }
  return out;
}

}  // namespace rockface::rockmass
