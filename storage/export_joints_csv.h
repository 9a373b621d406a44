#pragma once
// Joints as CSV for stereonet programs (Dips, Stereonet, OpenStereo, ...):
// one row per joint, header
//   id,dip,dip_direction,set,x,y,z,visit,source
// dip and dip direction in degrees (DESIGN.md conventions), x/y/z the point on
// the plane in absolute survey coordinates (datum added back; empty for an
// orientation-only joint), set the joint-set label (empty if unassigned).
// Fields holding commas, quotes or line breaks are quoted (RFC 4180).
#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

#include "storage/project_records.h"

namespace rockface::storage {

class ProjectStore;

void write_joints_csv(std::ostream& out, const std::vector<Joint>& joints,
                      const Eigen::Vector3d& datum);

// The joints of one visit (all visits when none given) to `file`; logs the
// export in the project when it is writable. Returns the number of joints.
std::size_t export_joints_csv(ProjectStore& store, const std::filesystem::path& file,
                              std::optional<RecordId> visit_id = {});

}  // namespace rockface::storage
