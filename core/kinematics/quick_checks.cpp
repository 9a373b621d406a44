#include "core/kinematics/quick_checks.h"

#include "core/kinematics/rotation_input.h"

namespace rockface::kinematics {

QuickChecks quick_checks(const blocks::Polyhedron& block, double uncertainty) {
  QuickChecks q;
  q.finiteness = block_finiteness(block, uncertainty);
  if (q.finiteness.finite.value) q.rotation = analyse_rotation(rotation_input(block), uncertainty);
  return q;
}

}  // namespace rockface::kinematics
