#pragma once
// The trace proposals (core/measure/proposals) as the propose workflow and
// the Mapping screen run them: on a 3D image whose lattice knows its pixels
// in the left photograph, or only its texture coordinates (a stored model),
// linked to the facets found on the same image; and their JSON for
// PROPOSALS.json ("trace_proposals", docs/scene-extensions.md).
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/measure/facets/facets.h"
#include "core/measure/proposals/proposal_search.h"
#include "core/measure/proposals/trace_proposals.h"

namespace rockface::app {

// The facets' outer outlines as the proposals take them.
std::vector<measure::ProposalFacet> proposal_facets(const measure::FacetSearch& facets);

// propose_traces with the preset's knobs and the model's depth precision
// (1 sigma, m) for the plane fits, as for a hand trace. A mesh with texture
// coordinates only gets its lattice's pixels from them (the inverse of
// firmware-app/records/project_mesh.cpp: u = (x + 0.5) / W,
// v = 1 - (y + 0.5) / H).
measure::ProposalResult propose_on_model(const photogrammetry::SurfaceMesh& mesh,
                                         const measure::MeshPicker& picker,
                                         const measure::PhotoView& view, const cv::Mat& photo,
                                         const std::vector<measure::ProposalFacet>& facets,
                                         Preset preset, double point_sigma_m, Progress& progress);

// The tablet's Find traces (issue 45: the first proposals within 2 s, the
// rest as they come): the proposals' cues and chains, the proposals of the
// longest chains handed to `batch` as soon as they are measured, then the
// facets of the model (the preset's knobs, `point_sigma_m` as their point
// precision), then the other chains' proposals, a batch at a time, then
// every proposal linked to the facets, ranked and named. The batches'
// proposals are unnamed and not linked to a facet; each is one of the
// result's. The result is that of find_facets then propose_on_model;
// `batch` may be empty (nothing handed out early).
using ProposalBatch = std::function<void(const std::vector<measure::TraceProposal>&)>;
measure::ProposalResult propose_first_then_facets(const photogrammetry::SurfaceMesh& mesh,
                                                  const measure::MeshPicker& picker,
                                                  const measure::PhotoView& view,
                                                  const cv::Mat& photo, Preset preset,
                                                  double point_sigma_m, Progress& progress,
                                                  const ProposalBatch& batch);

// {"proposals": [...], "notes": [...], ...}; coordinates absolute (+ datum).
nlohmann::json trace_proposals_json(const measure::ProposalResult& result,
                                    const Eigen::Vector3d& datum);

}  // namespace rockface::app
