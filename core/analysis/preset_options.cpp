#include "core/analysis/preset_options.h"

#include "core/kinematics/remote_axis.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::analysis {

PresetOptions preset_options(Preset preset) {
  PresetOptions o;
  o.preset = preset;
  o.reconstruction = photogrammetry::reconstruction_preset(preset);
  o.facets = measure::facet_options(preset);
  o.proposals = measure::proposal_options(preset);
  o.remote_axis_starts = kinematics::remote_axis_starts(preset);
  o.mechanics = mechanics::mechanics_options(preset);
  o.dynamics = mechanics::dynamics_options(preset);
  o.deviation = tunnel::deviation_options(preset);
  o.wedge_sagitta_m = tunnel::wedge_sagitta(preset);
  return o;
}

}  // namespace rockface::analysis
