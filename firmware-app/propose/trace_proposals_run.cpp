#include "firmware-app/propose/trace_proposals_run.h"

#include <memory>

#include "core/analysis/preset_options.h"
#include "core/common/units.h"
#include "firmware-app/measure/measures_json.h"
#include "firmware-app/propose/huge_page_images.h"
#include "firmware-app/propose/kept_working_memory.h"

namespace rockface::app {

using nlohmann::json;

std::vector<measure::ProposalFacet> proposal_facets(const measure::FacetSearch& facets) {
  std::vector<measure::ProposalFacet> out;
  out.reserve(facets.facets.size());
  for (const auto& f : facets.facets) out.push_back({f.id, f.outline});
  return out;
}

namespace {

// How many of the longest chains the first proposals come from: on the
// 24 Mpx dense face, a handful of the strongest traces, measured in a few
// hundredths of a second once the cues are found.
constexpr std::size_t kFirstChains = 16;
// The chains after the facets, this many at a time: each batch a fraction
// of a second on the dense 24 Mpx face, so the screen fills in steps the
// eye follows without a batch's hand-over costing anything measurable.
constexpr std::size_t kLaterChains = 64;

// The options of the preset with the model's depth precision.
measure::ProposalOptions options_for(Preset preset, double point_sigma_m) {
  measure::ProposalOptions options = analysis::preset_options(preset).proposals;
  options.measure.point_sigma = point_sigma_m;
  return options;
}

// A mesh with texture coordinates only, given its lattice's pixels from
// them (SurfaceMesh::pixels_from_texcoords); null when
// the mesh has its pixels already (or nothing to make them from).
std::unique_ptr<photogrammetry::SurfaceMesh> with_lattice(const photogrammetry::SurfaceMesh& mesh,
                                                          const cv::Mat& photo) {
  if (!mesh.pixels.empty() || photo.empty() || mesh.texcoords.size() != mesh.size()) return nullptr;
  auto lattice = std::make_unique<photogrammetry::SurfaceMesh>(mesh);
  lattice->pixels_from_texcoords(photo.cols, photo.rows);
  return lattice;
}

}  // namespace

measure::ProposalResult propose_on_model(const photogrammetry::SurfaceMesh& mesh,
                                         const measure::MeshPicker& picker,
                                         const measure::PhotoView& view, const cv::Mat& photo,
                                         const std::vector<measure::ProposalFacet>& facets,
                                         Preset preset, double point_sigma_m, Progress& progress) {
  const auto lattice = with_lattice(mesh, photo);
  return measure::propose_traces(lattice ? *lattice : mesh, picker, view, photo, facets,
                                 options_for(preset, point_sigma_m), progress, "proposals");
}

measure::ProposalResult propose_first_then_facets(const photogrammetry::SurfaceMesh& mesh,
                                                  const measure::MeshPicker& picker,
                                                  const measure::PhotoView& view,
                                                  const cv::Mat& photo, Preset preset,
                                                  double point_sigma_m, Progress& progress,
                                                  const ProposalBatch& batch) {
  const KeptWorkingMemory kept;
  const HugePageImages huge;
  std::unique_ptr<measure::ProposalSearch> search;
  {
    const auto lattice = with_lattice(mesh, photo);
    search = std::make_unique<measure::ProposalSearch>(lattice ? *lattice : mesh, picker, view,
                                                       photo, options_for(preset, point_sigma_m),
                                                       progress, "proposals");
  }
  if (batch) batch(search->longest(kFirstChains, progress));
  measure::MeasureSettings settings;
  settings.point_sigma = point_sigma_m;
  const measure::FacetSearch facets =
      measure::find_facets(mesh, settings, analysis::preset_options(preset).facets, progress);
  while (batch && search->chains_left() > 0) batch(search->longest(kLaterChains, progress));
  return search->finish(proposal_facets(facets), progress);
}

json trace_proposals_json(const measure::ProposalResult& r, const Eigen::Vector3d& datum) {
  json list = json::array();
  for (const auto& p : r.proposals) {
    json j;
    j["id"] = p.id;
    j["confidence"] = p.confidence;
    j["cue"] = measure::proposal_cue_name(p.cue);
    j["contrast_grey"] = p.contrast_grey;
    j["fold_deg"] = p.fold_deg;
    j["fold"] = p.fold_deg > 0 ? json(p.ridge ? "ridge" : "valley") : json(nullptr);
    j["dark_fraction"] = p.dark_fraction;
    j["fold_fraction"] = p.fold_fraction;
    j["facet"] = p.facet_id ? json(*p.facet_id) : json(nullptr);
    j["facet_fraction"] = p.facet_fraction;
    j["length_m"] = p.trace.length;
    j["censored_ends"] = {p.trace.censored_ends[0], p.trace.censored_ends[1]};
    json plane;
    put_plane_json(plane, p.trace.plane, datum);
    j["plane"] = plane;
    json pixels = json::array();
    for (const auto& px : p.trace.picks) pixels.push_back({px.pixel.x(), px.pixel.y()});
    j["photo"] = p.trace.picks.empty() ? json(nullptr) : json(p.trace.picks.front().photo);
    j["pixels"] = pixels;
    json points = json::array();
    for (const auto& q : p.trace.points) {
      const Eigen::Vector3d a = q + datum;
      points.push_back({a.x(), a.y(), a.z()});
    }
    j["points"] = points;
    list.push_back(j);
  }
  json out;
  out["proposals"] = list;
  out["notes"] = r.notes;
  out["line_noise"] = r.line_noise;
  out["dark_pixels"] = r.dark_pixels;
  out["fold_pixels"] = r.fold_pixels;
  return out;
}

}  // namespace rockface::app
