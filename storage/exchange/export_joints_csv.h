#pragma once
// Joints as CSV for stereonet programs (Dips, Stereonet, OpenStereo, ...):
// one row per joint, header
//   id,dip,dip_direction,set,x,y,z,visit,source,type,persistence
// dip and dip direction in degrees (DESIGN.md conventions), x/y/z the point on
// the plane in absolute survey coordinates (datum added back; empty for an
// orientation-only joint), set the joint-set label (empty if unassigned),
// type what was measured (trace, area, point; empty when given), persistence
// the trace length in metres (empty when not measured). Fields holding
// commas, quotes or line breaks are quoted (RFC 4180).
#include <filesystem>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "storage/project/project_records.h"

namespace rockface::storage {

class ProjectStore;

void write_joints_csv(std::ostream& out, const std::vector<Joint>& joints,
                      const Eigen::Vector3d& datum);

// Reads what write_joints_csv wrote (columns found by their header names,
// so a spreadsheet may reorder them; visit is not read). Points come back
// relative to `datum`. Throws InputError naming `where`, the line and the
// column for a bad row.
std::vector<Joint> read_joints_csv(std::istream& in, const Eigen::Vector3d& datum,
                                   const std::string& where);

// The joints of one visit (all visits when none given) to `file`; logs the
// export in the project when it is writable. Returns the number of joints.
std::size_t export_joints_csv(ProjectStore& store, const std::filesystem::path& file,
                              std::optional<RecordId> visit_id = {});

}  // namespace rockface::storage
