#pragma once
// The verdicts of a trace map while the geologist maps it (issue 28): a
// faces::TraceSession over the visit's free surface, fed the traces after
// every edit, so that only the regions an edit touched are computed again.
// Each block gets what the full analysis's block table starts with — finite,
// removable, the sliding mode and the limit-equilibrium factor of safety,
// with the margin — and none of its costly parts (rotation, remote axis,
// mechanics), which the Blocks screen's analysis adds.
#include <memory>

#include "core/analysis/analysis_input.h"
#include "core/common/progress.h"
#include "ui/app/field_services.h"

namespace rockface::app {

class MapVerdictSession {
 public:
  // The surface, the snapping tolerance, the orientation uncertainty, the
  // rock and the effects of `input` are the session's for its life; a scene
  // that changes them needs a new session. Throws InputError naming the
  // input for a scene without surface patches or with a bad one.
  explicit MapVerdictSession(const analysis::AnalysisInput& input);
  ~MapVerdictSession();
  MapVerdictSession(const MapVerdictSession&) = delete;
  MapVerdictSession& operator=(const MapVerdictSession&) = delete;

  // The blocks of input.traces (all of them, after an edit); the rest of
  // `input` is taken as the constructor's.
  ui::MapVerdicts update(const analysis::AnalysisInput& input, Progress& progress);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rockface::app
