#pragma once
// `rockface propose`'s one workflow, also the tablet's and the tests': a
// project's visit in (its first pair's 3D image, in the face frame), the
// planar facets found on it and the joint sets they form, the trace
// proposals on it, with the knobs used. Nothing is stored: the geologist accepts proposals by picks
// (`rockface measure`), as for hand-picked ones.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/measure/facets/facet_sets.h"
#include "core/measure/facets/facets.h"
#include "firmware-app/measure/measure_models.h"
#include "storage/project/project_records.h"

namespace rockface::app {

// Outer outline of each facet, by Facet::id, in the model frame
// (datum-relative): what the trace proposals take.
using FacetOutlines = std::map<int, std::vector<Eigen::Vector3d>>;

struct ProposeResult;

struct ProposeRequest {
  std::string project;
  std::optional<storage::RecordId> visit;  // default: the newest visit with a model
  Preset preset = Preset::standard;
  // Knobs set by hand over the preset's (qFacets lets the geologist set
  // them too); checked by check_facet_options.
  std::optional<double> angle_tolerance_deg, min_area_m2, planarity_in_sigmas;
  std::optional<int> smoothing_passes;
  // The trace proposals (core/measure/proposals/) on the same 3D image,
  // linked to these facets; off, PROPOSALS.json says they were not run.
  bool trace_proposals = true;
};

struct ProposeResult {
  storage::RecordId visit = 0;
  LoadedModel model;  // pair 1's 3D image, its photographs and datum
  std::string on;     // "visit 2: model 5", for the outputs
  measure::FacetSearch facets;
  measure::FacetSets sets;
  FacetOutlines outlines;
  nlohmann::json trace_proposals;  // trace_proposals_json(); null when not run
};

// InputError naming the project, --visit or the model for a missing file,
// visit or model.
ProposeResult propose_for_visit(const ProposeRequest& request, Progress& progress);

}  // namespace rockface::app
