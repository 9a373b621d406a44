// Blocks from the trace map: being built (issue 5). Until then a note says so.
#include "firmware-app/scene_analysis.h"

namespace rockface::app {
void analyse_trace_blocks(const storage::Scene&, storage::Report& report, Progress&) {
  report.notes.push_back("blocks from traces are not analysed by this build");
}
}  // namespace rockface::app
