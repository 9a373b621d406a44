#include "firmware-app/propose/trace_proposals_run.h"

#include "core/analysis/preset_options.h"
#include "core/common/units.h"
#include "firmware-app/measure/measures_json.h"

namespace rockface::app {

using nlohmann::json;

std::vector<measure::ProposalFacet> proposal_facets(const measure::FacetSearch& facets) {
  std::vector<measure::ProposalFacet> out;
  out.reserve(facets.facets.size());
  for (const auto& f : facets.facets) out.push_back({f.id, f.outline});
  return out;
}

measure::ProposalResult propose_on_model(const photogrammetry::SurfaceMesh& mesh,
                                         const measure::MeshPicker& picker,
                                         const measure::PhotoView& view, const cv::Mat& photo,
                                         const std::vector<measure::ProposalFacet>& facets,
                                         Preset preset, double point_sigma_m, Progress& progress) {
  measure::ProposalOptions options = analysis::preset_options(preset).proposals;
  options.measure.point_sigma = point_sigma_m;
  if (!mesh.pixels.empty() || photo.empty() || mesh.texcoords.size() != mesh.size())
    return measure::propose_traces(mesh, picker, view, photo, facets, options, progress,
                                   "proposals");
  photogrammetry::SurfaceMesh lattice = mesh;
  const float w = static_cast<float>(photo.cols), h = static_cast<float>(photo.rows);
  lattice.texture_width = photo.cols;
  lattice.texture_height = photo.rows;
  lattice.pixels.reserve(lattice.texcoords.size());
  for (const auto& t : lattice.texcoords)
    lattice.pixels.emplace_back(t.x() * w - 0.5f, (1.0f - t.y()) * h - 0.5f);
  return measure::propose_traces(lattice, picker, view, photo, facets, options, progress,
                                 "proposals");
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
