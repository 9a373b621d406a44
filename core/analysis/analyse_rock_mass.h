#pragma once
// The block report's `rockmass` section (docs/scene-extensions.md): the
// rock mass in figures of the analysed trace map, with the scene's form.
#include "core/analysis/analysis_input.h"
#include "core/analysis/report.h"

namespace rockface::analysis {

// Sets report.rockmass from the traces (sets: the joints' planes
// clustered; blocks: the finite blocks found from the traces). A trace map
// that makes no window (collinear traces) gets a note instead. Throws
// InputError naming the field for a form value out of range.
void analyse_rock_mass(const AnalysisInput& scene, Report& report);

}  // namespace rockface::analysis
