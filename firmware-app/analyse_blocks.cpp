// Explicit scene blocks: being built (issue 3). Until then a note says so.
#include "firmware-app/scene_analysis.h"

namespace rockface::app {
void analyse_scene_blocks(const storage::Scene&, storage::Report& report, Progress&) {
  report.notes.push_back("explicit blocks are not analysed by this build");
}
}  // namespace rockface::app
