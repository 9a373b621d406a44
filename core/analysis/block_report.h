#pragma once
// The report entry of one analysed block, the same for explicit scene blocks
// and blocks found from traces: corners, mass properties, face areas, mode,
// factor of safety, notes, and — for finite blocks — rotatability.
#include "core/analysis/analysis_input.h"
#include "core/analysis/report.h"
#include "core/blocks/polyhedron.h"
#include "core/kinematics/block_analysis.h"

namespace rockface::analysis {

void fill_block_report(const blocks::Polyhedron& poly, const kinematics::BlockAnalysis& analysis,
                       const SceneAnalysis& options, ReportBlock& rb);

}  // namespace rockface::analysis
