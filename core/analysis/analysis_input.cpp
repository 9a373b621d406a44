#include "core/analysis/analysis_input.h"

namespace rockface::analysis {

std::vector<std::string> SceneEffects::listed() const {
  std::vector<std::string> names{"gravity"};
  if (water) names.push_back("water");
  if (seismic) names.push_back("seismic");
  if (insitu_stress) names.push_back("insitu_stress");
  if (!forces.empty()) names.push_back("forces");
  if (!bolts.empty()) names.push_back("bolts");
  if (joint_law) names.push_back("joint_law");
  return names;
}

}  // namespace rockface::analysis
