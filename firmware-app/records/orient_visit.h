#pragma once
// North for a visit stored without it (issue 42): a compass line given after
// the fact — its two pixels in the left photograph of the visit's first
// pair and its bearing, as the geologist read it on site — turns the visit's
// 3D images about the vertical, as the reconstruction would have with the
// line (photogrammetry::north_rotation), and records that north came from
// the compass. The tablet and `rockface orient` both call it.
#include <string>

#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "storage/project/project_store.h"

namespace rockface::app {

struct VisitOrientation {
  double turned_deg = 0;  // about the vertical, + counter-clockwise seen from above
  std::string note;       // "north from the compass line at 087.5°"
};

// Throws InputError naming the visit (no 3D image; measured, placed or
// registered by control points already: their frame would change under
// them) or the line (`north.where`: off the 3D image, vertical).
VisitOrientation orient_visit_by_compass(storage::ProjectStore& store, storage::RecordId visit_id,
                                         const photogrammetry::NorthReference& north);

}  // namespace rockface::app
