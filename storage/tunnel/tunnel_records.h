#pragma once
// The tunnel as a project stores it (schema 5): one tunnel per project (its
// name, alignment table, design profile, drive direction, underbreak
// tolerance), and per visit its place in the tunnel and how it was found.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/visit_placement.h"
#include "storage/project/project_records.h"
#include "storage/tunnel/built_alignment.h"

namespace rockface::storage {

struct TunnelRecord {
  std::string name;
  // The surveyor's table as read (survey coordinates; radii empty for a
  // polyline); build the Alignment with the project's datum.
  std::vector<tunnel::AlignmentStation> stations;
  std::vector<double> radii;
  bool polyline = false;
  tunnel::DesignProfile profile;
  tunnel::Drive drive = tunnel::Drive::ascending;
  double underbreak_tolerance_m = 0.05;
  std::string alignment_source, profile_source;  // the files they came from
  std::string created_at;                        // empty = now

  // The alignment relative to datum: built once per datum and table, and
  // shared by the record's copies (built_alignment.h).
  tunnel::Alignment alignment(const Eigen::Vector3d& datum) const;
  std::shared_ptr<BuiltAlignment> built = std::make_shared<BuiltAlignment>();
};

// How a visit was placed in the tunnel (the geometry and how it was found:
// core/tunnel/visit_placement.h), as the project stores it: which visit, and
// when.
struct VisitPlacement : tunnel::VisitPlacement {
  RecordId visit_id = 0;
  std::string created_at;  // empty = now
};
const char* placement_method_name(
    VisitPlacement::Method m);  // "ground_control" | "chainage_compass"

}  // namespace rockface::storage
