#pragma once
// Placing a visit by the chainage the geologist types (no survey target in
// view): the range pole's lower target stood at a chainage, an offset and a
// height above the axis. The visit's 3D images (oriented north by the
// compass line and levelled by the pole) are moved there as new models of
// their captures (the originals stay stored), and the visit is placed from
// the moved surface. Refused once the visit has measurements: they lie in
// the frame before the move.
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::app {

struct TypedChainage {
  double chainage = 0;
  double offset = 0;  // m, + right of the axis looking in the drive direction
  double height = 0;  // m above the alignment's axis
};

// Throws InputError naming what is missing (no tunnel, no 3D image, no pole
// targets in it, measurements already made, a chainage off the alignment).
storage::VisitPlacement place_by_typed_chainage(storage::ProjectStore& store,
                                                storage::RecordId visit_id,
                                                const TypedChainage& typed);

}  // namespace rockface::app
