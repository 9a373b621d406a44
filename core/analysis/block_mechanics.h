#pragma once
// The equilibrium-path analysis of one block, when the scene asks for it
// (analysis.stability = "equilibrium_path"): joint laws from
// effects.joint_law when the scene gives one, else each joint Coulomb with
// its own friction and cohesion; options from the preset and the scene's
// analysis fields; the result as the block's report `mechanics`.
#include "core/analysis/analysis_input.h"
#include "core/analysis/report.h"
#include "core/blocks/mass_properties.h"
#include "core/blocks/polyhedron.h"
#include "core/common/progress.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect.h"

namespace rockface::analysis {

// The report's mechanics.joint_law when the scene gives no effects.joint_law:
// each joint Coulomb with its own friction and cohesion, stiff, no dilation.
inline constexpr const char* kDefaultJointLawName = "coulomb (scene friction/cohesion)";

bool scene_wants_mechanics(const AnalysisInput& scene);

// Runs the equilibrium path of a finite block and fills rb.mechanics.
// strengths: per polyhedron plane, the joints' friction and cohesion as
// limit equilibrium takes them (kinematics::BlockAnalysisInput). Throws
// InputError naming the scene file and field for bad parameters; progress
// (optional) sees each continuation step and may cancel.
void analyse_block_mechanics(const blocks::Polyhedron& poly, const AnalysisInput& scene,
                             const std::vector<kinematics::JointStrength>& strengths,
                             const kinematics::Effects& effects, ReportBlock& rb,
                             Progress* progress = nullptr);

}  // namespace rockface::analysis
