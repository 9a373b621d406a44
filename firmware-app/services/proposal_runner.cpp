// The Mapping screen's trace proposals (ui::ProposalRunner): the facets of
// the model the screen holds, then the proposals on it linked to them, as
// `rockface propose` finds both (firmware-app/propose).
#include "core/analysis/preset_options.h"
#include "core/common/error.h"
#include "core/measure/facets/facets.h"
#include "firmware-app/propose/trace_proposals_run.h"
#include "firmware-app/services/ui_services.h"

namespace rockface::app {

measure::ProposalResult FieldProposalRunner::propose(const ui::ProposalInput& input,
                                                     Progress& progress) {
  if (!input.mesh || !input.picker || !input.view)
    throw InputError("proposals", "no 3D image with its photograph's camera on display");
  measure::MeasureSettings settings;
  settings.point_sigma = input.point_sigma_m;
  const measure::FacetSearch facets = measure::find_facets(
      *input.mesh, settings, analysis::preset_options(input.preset).facets, progress);
  return propose_on_model(*input.mesh, *input.picker, *input.view, input.photo,
                          proposal_facets(facets), input.preset, input.point_sigma_m, progress);
}

}  // namespace rockface::app
