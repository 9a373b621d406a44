// The Mapping screen's trace proposals (ui::ProposalRunner): the facets of
// the model the screen holds and the proposals on it linked to them, as
// `rockface propose` finds both (firmware-app/propose), the proposals' cues
// first and the proposals handed to the screen as they are measured
// (propose_first_then_facets).
#include "core/common/error.h"
#include "firmware-app/propose/trace_proposals_run.h"
#include "firmware-app/services/ui_services.h"

namespace rockface::app {

measure::ProposalResult FieldProposalRunner::propose(const ui::ProposalInput& input,
                                                     Progress& progress, const Batch& batch) {
  if (!input.mesh || !input.picker || !input.view)
    throw InputError("proposals", "no 3D image with its photograph's camera on display");
  // The cues before the facets, so that the screen has the longest chains'
  // proposals within 2 s (issue 45), then the rest in batches.
  return propose_first_then_facets(*input.mesh, *input.picker, *input.view, input.photo,
                                   input.preset, input.point_sigma_m, progress, batch);
}

}  // namespace rockface::app
