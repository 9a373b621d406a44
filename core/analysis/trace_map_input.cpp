#include "core/analysis/trace_map_input.h"

#include <algorithm>

#include "core/common/units.h"

namespace rockface::analysis {

TraceMapInput trace_map_input(const AnalysisInput& input) {
  TraceMapInput map;
  // Without a datum, the first patch corner is the origin, so survey
  // coordinates lose no precision either.
  map.datum = input.has_datum ? input.datum : input.patches[0].polygon[0];
  // A zero tolerance would merge nothing and divide the snapping grid by zero;
  // a micrometre merges rounding only.
  map.snap_tolerance = std::max(input.analysis.snap_tolerance, 1e-6);
  map.orientation_uncertainty = deg_to_rad(input.analysis.orientation_uncertainty_deg);
  const Eigen::Vector3d& datum = map.datum;
  for (const auto& p : input.patches) {
    faces::PatchInput in{p.id, {}};
    for (const auto& x : p.polygon) in.polygon.push_back(x - datum);
    map.patches.push_back(std::move(in));
  }
  for (const auto& t : input.traces) {
    faces::TraceInput in;
    in.id = t.id;
    if (t.joint) {
      const SceneJoint* j = input.joint(*t.joint);
      faces::TraceJoint tj;
      tj.index = input.plane_index(j->id);
      tj.id = j->id;
      tj.orientation = {deg_to_rad(j->dip), deg_to_rad(j->dipdir)};
      if (j->friction) tj.friction = deg_to_rad(*j->friction);
      tj.cohesion = j->cohesion.value_or(0.0);
      in.joint = tj;
    }
    for (const auto& x : t.points) in.points.push_back(x - datum);
    map.traces.push_back(std::move(in));
  }
  return map;
}

}  // namespace rockface::analysis
