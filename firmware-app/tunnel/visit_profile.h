#pragma once
// The excavation of a visit's round against the design profile
// (`rockface profile`, the field report, the tablet's Tunnel view): the
// visit's surface cut by cross-sections from the previous round's face to
// this one, with the over- and underbreak in numbers and as a developed view.
#include <optional>
#include <string>
#include <vector>

#include "core/common/preset.h"
#include "core/tunnel/profile_deviation.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::app {

struct VisitProfile {
  storage::TunnelRecord tunnel;
  storage::VisitPlacement placement;
  // The round evaluated: from the previous visit's face (in drive order) to
  // 0.15 m short of where this face reaches farthest back (a section through
  // the face would cut it); the first visit's round starts where its
  // surface starts.
  double round_from = 0, round_to = 0;
  std::string round_from_source;  // "face of visit 3" | "start of the 3D image"
  tunnel::ProfileDeviation deviation;
  std::size_t pole_vertices = 0;  // surface vertices not counted: the range pole
};

// The face a round that ends at `round_to` starts from: the nearest stored
// placement of another visit behind it in the drive's sense (`sense` +1
// ascending, -1 descending), none when no visit lies behind. The round
// starts there unless the 3D image starts farther on (VisitProfile).
std::optional<storage::VisitPlacement> previous_face(
    const std::vector<storage::VisitPlacement>& placements, storage::RecordId visit_id,
    double round_to, double sense);

// Throws InputError naming the project or visit when the project has no
// tunnel, the visit is not placed in it, or it has no 3D image.
VisitProfile visit_profile(storage::ProjectStore& store, storage::RecordId visit_id,
                           Preset preset = Preset::standard);

}  // namespace rockface::app
