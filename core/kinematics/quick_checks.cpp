#include "core/kinematics/quick_checks.h"

#include "core/common/parallel.h"
#include "core/kinematics/rotation_input.h"

namespace rockface::kinematics {

QuickChecks quick_checks(const blocks::Polyhedron& block, double uncertainty) {
  QuickChecks q;
  q.finiteness = block_finiteness(block, uncertainty);
  if (q.finiteness.finite.value) q.rotation = analyse_rotation(rotation_input(block), uncertainty);
  return q;
}

std::vector<QuickChecks> quick_checks_all(const std::vector<blocks::Polyhedron>& blocks,
                                          double uncertainty, unsigned threads) {
  std::vector<QuickChecks> out(blocks.size());
  parallel_for(
      blocks.size(), [&](size_t i) { out[i] = quick_checks(blocks[i], uncertainty); }, threads);
  return out;
}

}  // namespace rockface::kinematics
