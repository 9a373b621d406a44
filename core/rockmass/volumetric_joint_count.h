#pragma once
// Palmström's volumetric joint count (joints per m3; Palmström 1982, 2005):
//   Jv = sum_i 1 / S_i + N_r / (5 sqrt(A)),
// S_i the normal spacing of set i (m), N_r the random joints (traces of no
// set) seen on a face of area A (m2). Beside it, what Jv tells of RQD
// (Palmström 2005: RQD = 110 - 2.5 Jv, 0..100) and of the block volume
// (Vb = beta Jv^-3, beta the block shape factor; 27 for cubes).
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/spacing.h"

namespace rockface::rockmass {

struct VolumetricJointCount {
  std::optional<double> jv;  // per m3; nullopt when no set has a spacing
  double from_sets = 0, from_random = 0;
  int sets_used = 0, random_traces = 0;
  double window_area_m2 = 0;
  std::optional<double> rqd_palmstrom;  // 110 - 2.5 Jv
  std::vector<std::string> sets_without_spacing;
};

VolumetricJointCount volumetric_joint_count(const std::vector<SetSpacing>& spacings,
                                            int random_traces, double window_area_m2);

}  // namespace rockface::rockmass
