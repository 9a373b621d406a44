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
  if (!input.mesh->pixels.empty() || input.photo.empty() ||
      input.mesh->texcoords.size() != input.mesh->size())
    return measure::propose_traces(*input.mesh, *input.picker, *input.view, input.photo, {},
                                   options, progress, "proposals");
  // The model view keeps texture coordinates only: the lattice's pixels in
  // the photograph are theirs inverted (as firmware-app/records/project_mesh.cpp:
  // u = (x + 0.5) / W, v = 1 - (y + 0.5) / H).
  photogrammetry::SurfaceMesh mesh = *input.mesh;
  const float w = static_cast<float>(input.photo.cols), h = static_cast<float>(input.photo.rows);
  mesh.texture_width = input.photo.cols;
  mesh.texture_height = input.photo.rows;
  mesh.pixels.reserve(mesh.texcoords.size());
  for (const auto& t : mesh.texcoords)
    mesh.pixels.emplace_back(t.x() * w - 0.5f, (1.0f - t.y()) * h - 0.5f);
  return measure::propose_traces(mesh, *input.picker, *input.view, input.photo, {}, options,
                                 progress, "proposals");
}

}  // namespace rockface::app
