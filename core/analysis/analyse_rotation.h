#pragma once
// Rotational kinematics of one block for the report (issue 4): corner and
// edge rotatability about the block's static points and joint / free-face
// edges, and the remote-axis search, as the scene's analysis options ask.
#include "core/analysis/analysis_input.h"
#include "core/analysis/report.h"
#include "core/blocks/polyhedron.h"

namespace rockface::analysis {

// Fills out.rotation when analysis.rotation is set, and out.remote_axis when
// analysis.remote_axis is given (its starts and seed); leaves each unset
// otherwise. Joints and free faces are the polyhedron's plane kinds (a
// stiff lining is a joint). Vertex indices in the report are the
// polyhedron's, the order of ReportBlock::vertices; the remote axis point is
// absolute (block.datum() added back); rotation-space rays and axis
// directions are unit vectors. Verdicts whose margin is inside
// analysis.orientation_uncertainty_deg are marked marginal. Adds a note to
// out.notes when the only axis found is so far away that the motion is
// essentially a translation. Throws rockface::InputError for a remote-axis
// start count below 1 (naming analysis.remote_axis.starts).
void analyse_block_rotation(const blocks::Polyhedron& block, const SceneAnalysis& analysis,
                            ReportBlock& out);

}  // namespace rockface::analysis
