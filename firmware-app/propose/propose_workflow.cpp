#include "firmware-app/propose/propose_workflow.h"

#include <filesystem>

#include "core/analysis/preset_options.h"
#include "core/common/error.h"
#include "core/measure/mesh_picker.h"
#include "firmware-app/propose/huge_page_images.h"
#include "firmware-app/propose/kept_working_memory.h"
#include "firmware-app/propose/trace_proposals_run.h"
#include "storage/project/project_store.h"

namespace rockface::app {

ProposeResult propose_for_visit(const ProposeRequest& request, Progress& progress) {
  if (!std::filesystem::exists(request.project))
    throw InputError(request.project, "no such project file");
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(request.project, read);
  ModelSource source;
  source.source = request.project;
  source.visit = request.visit;
  if (!source.visit) {
    // The newest visit with a model (as `rockface measure` chooses).
    const auto visits = store.list_visits();
    for (auto v = visits.rbegin(); v != visits.rend() && !source.visit; ++v)
      if (!store.list_visit_models(v->id).empty()) source.visit = v->id;
    if (!source.visit) throw InputError(request.project, "the project has no visit with a model");
  }
  const ProjectPairs pairs = project_pairs(store, source);
  ProposeResult r;
  // Pair 1: its mesh frame is the face frame the measurements use; further
  // pairs overlap it and would give the same facets twice.
  r.model = load_stored_model(store, source, pairs.models[0], 1);
  r.on = pairs.what + ": model " + std::to_string(pairs.models[0]);
  r.visit = *source.visit;
  // Issue 38: the facets' and proposals' thresholds are metres and square
  // metres; on a 3D image in units of the base they would mean anything.
  if (!r.model.scaled)
    throw InputError(request.project + ", visit " + std::to_string(r.visit),
                     "its 3D image is unscaled (no range pole, control points or baseline): its "
                     "lengths are in units of the camera base, and the thresholds of `propose` "
                     "are in metres; replay or reconstruct the pair with a range pole in view "
                     "(--range-pole) or control points (--gcp)");
  const KeptWorkingMemory kept;  // for the facets' and proposals' working arrays
  const HugePageImages huge;     // and their large images
  measure::MeasureSettings settings;
  settings.point_sigma = r.model.point_sigma;
  settings.correlation_length = r.model.correlation_length;
  measure::FacetOptions options = analysis::preset_options(request.preset).facets;
  if (request.angle_tolerance_deg) options.angle_tolerance_deg = *request.angle_tolerance_deg;
  if (request.min_area_m2) options.min_area_m2 = *request.min_area_m2;
  if (request.planarity_in_sigmas) options.planarity_in_sigmas = *request.planarity_in_sigmas;
  if (request.smoothing_passes) options.smoothing_passes = *request.smoothing_passes;
  r.facets = measure::find_facets(r.model.mesh, settings, options, progress);
  r.sets = measure::facet_sets(r.facets);
  for (const auto& f : r.facets.facets) r.outlines[f.id] = f.outline;
  if (request.trace_proposals) {
    const auto view = r.model.views.find("left");
    const auto photo = r.model.photos.find("left");
    if (view == r.model.views.end() || photo == r.model.photos.end() || photo->second.empty())
      throw InputError(r.on, "no left photograph stored with the 3D image: no trace proposals");
    const measure::MeshPicker picker(r.model.mesh);
    r.trace_proposals = trace_proposals_json(
        propose_on_model(r.model.mesh, picker, view->second, photo->second,
                         proposal_facets(r.facets), request.preset, r.model.point_sigma, progress),
        r.model.datum);
  }
  return r;
}

}  // namespace rockface::app
