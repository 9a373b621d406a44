#pragma once
// The block analysis: its input as values (analysis_input.h) in, a report
// out. Each part of the analysis is one function in its own file; analyse
// runs the parts the input asks for, times them and lists the effects used.
#include "core/analysis/analysis_input.h"
#include "core/analysis/report.h"
#include "core/common/progress.h"

namespace rockface::analysis {

Report analyse(const AnalysisInput& scene, Progress& progress);

// Joint pyramids against every free face or face group (analyse_pyramids.cpp).
void analyse_pyramids(const AnalysisInput& scene, Report& report);
// The scene's explicit blocks (analyse_blocks.cpp).
void analyse_scene_blocks(const AnalysisInput& scene, Report& report, Progress& progress);
// Blocks found from the trace map on the free surface (analyse_traces.cpp).
void analyse_trace_blocks(const AnalysisInput& scene, Report& report, Progress& progress);

}  // namespace rockface::analysis
