#pragma once
// The free surface and the traces of an analysis input as the trace map
// takes them (core/faces): datum-relative, angles in radians, with the
// snapping tolerance and the orientation uncertainty the map is built with.
// Shared by the analysis and the verdict benchmark (tools/bench).
#include <vector>

#include <Eigen/Core>

#include "core/analysis/analysis_input.h"
#include "core/faces/free_surface.h"
#include "core/faces/trace_network.h"

namespace rockface::analysis {

struct TraceMapInput {
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();  // absolute; the rest is relative to it
  double snap_tolerance = 0;                        // m
  double orientation_uncertainty = 0;               // rad
  std::vector<faces::PatchInput> patches;
  std::vector<faces::TraceInput> traces;
};

// `input` must have one surface patch or more.
TraceMapInput trace_map_input(const AnalysisInput& input);

}  // namespace rockface::analysis
