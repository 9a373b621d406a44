#pragma once
// The tunnel as a project stores it (schema 5): one tunnel per project (its
// name, alignment table, design profile, drive direction, underbreak
// tolerance), and per visit its place in the tunnel and how it was found.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "storage/project/project_records.h"

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

  tunnel::Alignment alignment(const Eigen::Vector3d& datum) const;
};

// How a visit was placed in the tunnel.
struct VisitPlacement {
  enum class Method {
    ground_control,    // monitoring targets with survey coordinates seen in the photographs
    chainage_compass,  // the chainage the geologist typed plus the compass line
  };
  RecordId visit_id = 0;
  Method method = Method::chainage_compass;
  double chainage = 0;  // of the face
  double offset_m = 0;  // of the face's centre from the axis, + right
  std::optional<double> height_m;
  // Ground control: residuals of the targets (label, dx, dy, dz in m) and
  // their rms; chainage + compass: the compass azimuth used (degrees).
  std::vector<RegistrationResidual> residuals;
  std::optional<double> rms_m;
  std::optional<double> compass_azimuth_deg;
  std::string note;
  std::string created_at;  // empty = now
};
const char* placement_method_name(
    VisitPlacement::Method m);  // "ground_control" | "chainage_compass"

}  // namespace rockface::storage
