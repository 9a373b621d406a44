// The Mapping screen's trace proposals (ui::ProposalRunner): the facets of
// the model the screen holds and the proposals on it linked to them, as
// `rockface propose` finds both (firmware-app/propose), the proposals' cues
// first (propose_first_then_facets).
#include "core/common/error.h"
#include "firmware-app/propose/trace_proposals_run.h"
#include "firmware-app/services/ui_services.h"

namespace rockface::app {

measure::ProposalResult FieldProposalRunner::propose(const ui::ProposalInput& input,
                                                     Progress& progress) {
  if (!input.mesh || !input.picker || !input.view)
    throw InputError("proposals", "no 3D image with its photograph's camera on display");
  // The cues before the facets, so that a screen handed the first
  // proposals has them within 2 s (issue 45); the Mapping screen takes the
  // whole result for now.
  return propose_first_then_facets(*input.mesh, *input.picker, *input.view, input.photo,
                                   input.preset, input.point_sigma_m, progress, {});
}

}  // namespace rockface::app
