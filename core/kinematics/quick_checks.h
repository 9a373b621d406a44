#pragma once
// The quick geometric checks of one block (issue 17): finiteness and
// removability with their margins (block_analysis.h) and corner / edge
// rotatability (rotation_space.h), the checks that always run and that the
// geologist wants for every block before the next excavation round.
#include <vector>

#include "core/blocks/polyhedron.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/rotation_space.h"

namespace rockface::kinematics {

struct QuickChecks {
  Finiteness finiteness;
  RotationAnalysis rotation;  // empty for a block that is not finite
};

// uncertainty: orientation uncertainty of the planes, radians. Rotation is
// analysed for finite blocks only (an infinite block has no corners to
// rotate about that mean anything), as the report does.
QuickChecks quick_checks(const blocks::Polyhedron& block, double uncertainty);

// The quick checks of every block, on `threads` threads (0: all cores, see
// core/common/parallel.h); results in the order of the blocks and equal,
// number for number, to calling quick_checks() on each in turn.
std::vector<QuickChecks> quick_checks_all(const std::vector<blocks::Polyhedron>& blocks,
                                          double uncertainty, unsigned threads = 0);

}  // namespace rockface::kinematics
