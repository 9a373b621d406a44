#pragma once
// Joint traces as CSV for Dips and spreadsheets: one row per trace, header
//   id,dip,dip_direction,set,joint,trace_length_m,censored,x,y,z,x_from,y_from,z_from,x_to,y_to,z_to,origin,visit
// dip / dip direction of the trace's fitted plane in degrees (DESIGN.md
// conventions; empty when the trace could not be fitted: collinear), set
// the joint set of the joint the trace belongs to (empty when unassigned),
// trace_length_m along its points, censored "yes" when an end leaves the
// mapped area (the length is a lower bound), x/y/z its middle point and its
// two ends in absolute survey coordinates (datum added back, 0.1 mm).
#include <ostream>
#include <vector>

#include <Eigen/Core>

#include "storage/project/project_records.h"

namespace rockface::storage {

// Traces among `measurements` (areas and points are left out); `joints`
// give each trace's set through its joint's label.
std::size_t write_traces_csv(std::ostream& out, const std::vector<Measurement>& measurements,
                             const std::vector<Joint>& joints, const Eigen::Vector3d& datum);

}  // namespace rockface::storage
