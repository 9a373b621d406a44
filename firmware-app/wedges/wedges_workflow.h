#pragma once
// `rockface wedges`' one workflow, also the tablet's: a scene file or a
// project's visit in, the wedge analysis out.
#include <optional>
#include <string>

#include "core/tunnel/wedge_analysis.h"
#include "firmware-app/wedges/wedge_input.h"

namespace rockface::app {

struct WedgesRequest {
  std::string input;                       // SCENE.json or PROJECT.rockface
  std::optional<storage::RecordId> visit;  // project: default the latest visit
  std::optional<std::string> axis;         // "TREND/PLUNGE"
  std::optional<std::string> preset;       // default: the scene's, or standard
  // Project runs only (a scene gives them in its `wedges` section):
  std::optional<double> friction_deg, cohesion_pa, trace_length_m;
  std::optional<std::string> bolts;      // "LENGTH,SPACING,CAPACITY[,BOND]"
  std::optional<std::string> shotcrete;  // "THICKNESS,SHEAR_STRENGTH"
};

struct WedgesResult {
  WedgeRun run;
  tunnel::WedgeAnalysis analysis;
};

// A scene when the file is JSON, else a project. InputError names the file
// and field (or option) for bad input.
WedgesResult wedges_from_input(const WedgesRequest& request);

// The project's wedges for one visit with the default settings (the
// tablet and the field report): none when the project has no tunnel or
// the visit fewer than three sets (`why` says which).
std::optional<WedgesResult> project_visit_wedges(storage::ProjectStore& store,
                                                 storage::RecordId visit, std::string* why);

}  // namespace rockface::app
