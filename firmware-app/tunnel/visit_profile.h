#pragma once
// The excavation of a visit's round against the design profile
// (`rockface profile`, the field report, the tablet's Tunnel view): the
// visit's surface cut by cross-sections from the previous round's face to
// this one, with the over- and underbreak in numbers and as a developed view.
#include <optional>
#include <string>
#include <vector>

#include "core/common/preset.h"
#include "core/tunnel/lining_precision.h"
#include "core/tunnel/profile_deviation.h"
#include "firmware-app/tunnel/round_start.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::app {

struct VisitProfile {
  storage::TunnelRecord tunnel;
  storage::VisitPlacement placement;
  // The round evaluated: from the previous face of the visit's heading (in
  // its drive direction, round_start.h) to 0.4 m short of where this face
  // reaches farthest back (a section through the face would cut it); the
  // heading's first visit's round starts where its surface starts.
  double round_from = 0, round_to = 0;
  std::string round_from_source;  // "face of visit 3" | "start of the 3D image"
  // The heading's drive direction the round was read in: +1 toward
  // ascending chainage, -1 descending; the previous face of the heading
  // behind round_to (its chainage), whether or not the round starts there.
  double sense = 1;
  std::optional<double> previous_face;
  tunnel::ProfileDeviation deviation;
  // Issue 38: each cell's noise threshold from its own predicted precision
  // (lining_precision.h) when the models record their pairs' geometry: the
  // figures (absent otherwise: the stated sigma holds for every cell), and
  // each cell's sigma (row-major as deviation.view, NaN where no value).
  std::optional<tunnel::CellPrecisionFigures> cell_precision;
  std::vector<float> cell_sigma_m;
  std::size_t pole_vertices = 0;  // surface vertices not counted: the range pole
};

// Throws InputError naming the project or visit when the project has no
// tunnel, the visit is not placed in it, or it has no 3D image.
// `drive`: the project's faces (round_start.h's drive_faces) when the
// caller reads every round of a drive, so that they are read once, not
// once per round; else read here.
VisitProfile visit_profile(storage::ProjectStore& store, storage::RecordId visit_id,
                           Preset preset = Preset::standard, const DriveFaces* drive = nullptr);

}  // namespace rockface::app
