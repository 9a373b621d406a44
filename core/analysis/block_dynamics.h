#pragma once
// The block's motion after failure, when the scene asks for it
// (analysis.dynamics): for a block that fails under its loads (limit
// equilibrium FoS < 1, or the equilibrium path finds no equilibrium) or at
// the limit point of its equilibrium path, simulate how it moves
// (core/mechanics/dynamics) and fill the block's report `dynamics`.
#include <functional>
#include <map>
#include <string>

#include "core/analysis/analysis_input.h"
#include "core/analysis/report.h"
#include "core/blocks/polyhedron.h"
#include "core/common/progress.h"
#include "core/kinematics/effects/effect.h"

namespace rockface::analysis {

bool scene_wants_dynamics(const AnalysisInput& scene);

// Runs after limit equilibrium and the equilibrium path have filled rb.
// Blocks that do not fail get a note, not a simulation. Throws InputError
// naming the scene file and field for bad parameters.
// friction_deg (optional): the friction angle of joint planes by plane
// name, where the scene's joints do not name them (blocks from traces).
void analyse_block_dynamics(const blocks::Polyhedron& poly, const AnalysisInput& scene,
                            const kinematics::Effects& effects, ReportBlock& rb,
                            Progress* progress = nullptr,
                            const std::map<std::string, double>* friction_deg = nullptr);

// Renames the planes the block's dynamics names (events, friction) with
// `name` (a trace block's planes take their joint's id).
void rename_dynamics_planes(ReportDynamics& d,
                            const std::function<std::string(const std::string&)>& name);

}  // namespace rockface::analysis
