#pragma once
// The block report's `rockmass` section (docs/scene-extensions.md): the
// rock mass in figures of the analysed trace map, with the scene's form.
#include "core/analysis/report.h"
#include "firmware-app/analysis/analysis_input.h"

namespace rockface::app {

// Sets report.rockmass from the traces (sets: the joints' planes
// clustered; blocks: the finite blocks found from the traces). A trace map
// that makes no window (collinear traces) gets a note instead. Throws
// InputError naming the field for a form value out of range.
void analyse_rock_mass(const AnalysisInput& scene, analysis::Report& report);

}  // namespace rockface::app
