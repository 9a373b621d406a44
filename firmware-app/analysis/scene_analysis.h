#pragma once
// The composition of `rockface analyse`: a parsed scene in, a report out.
// Each part of the analysis is one function in its own file; analyse_scene
// runs the parts the scene asks for, times them and lists the effects used.
#include "core/common/progress.h"
#include "storage/report.h"
#include "storage/scene.h"

namespace rockface::app {

storage::Report analyse_scene(const storage::Scene& scene, Progress& progress);

// Joint pyramids against every free face or face group (analyse_pyramids.cpp).
void analyse_pyramids(const storage::Scene& scene, storage::Report& report);
// The scene's explicit blocks (analyse_blocks.cpp).
void analyse_scene_blocks(const storage::Scene& scene, storage::Report& report, Progress& progress);
// Blocks found from the trace map on the free surface (analyse_traces.cpp).
void analyse_trace_blocks(const storage::Scene& scene, storage::Report& report, Progress& progress);

}  // namespace rockface::app
