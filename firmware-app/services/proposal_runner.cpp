// The Mapping screen's trace proposals (ui::ProposalRunner): the core
// function over the model the screen holds, with the preset's knobs and
// the model's depth precision for the plane fits (as for a hand trace).
#include "core/common/error.h"
#include "firmware-app/services/ui_services.h"

namespace rockface::app {

measure::ProposalResult FieldProposalRunner::propose(const ui::ProposalInput& input,
                                                     Progress& progress) {
  if (!input.mesh || !input.picker || !input.view)
    throw InputError("proposals", "no 3D image with its photograph's camera on display");
  measure::ProposalOptions options = measure::proposal_options(input.preset);
  options.measure.point_sigma = input.point_sigma_m;
  return measure::propose_traces(*input.mesh, *input.picker, *input.view, input.photo, {}, options,
                                 progress, "proposals");
}

}  // namespace rockface::app
