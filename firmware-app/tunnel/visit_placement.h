#pragma once
// A stored visit's place in the tunnel: its 3D images and their registration
// read from the project, placed by core/tunnel/visit_placement.h.
#include <optional>
#include <string>

#include "core/tunnel/alignment.h"
#include "core/tunnel/visit_placement.h"
#include "firmware-app/tunnel/visit_surface.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::app {

// How the surface's first 3D image came into the project frame, from its
// stored registration (kind, residuals, rms, the compass azimuth in its
// parameters). `typed`: a note saying how the pole's place was given
// ("chainage 112.00 typed"); empty when the pole's position was surveyed.
tunnel::FrameRegistration frame_registration(const VisitSurface& surface,
                                             const std::string& typed = {});

// The placement of the visit `visit_id` as the project stores it. Throws
// InputError naming the visit when its surface lies off the alignment.
storage::VisitPlacement place_visit(const tunnel::Alignment& alignment,
                                    const tunnel::DesignProfile& profile,
                                    const VisitSurface& surface, storage::RecordId visit_id,
                                    const std::string& typed = {});

// The visit's stored placement; else, when its 3D image was registered to
// monitoring targets with survey coordinates (`rockface reconstruct --gcp`),
// the placement read from that image (not stored: the store may be
// read-only); else nothing.
std::optional<storage::VisitPlacement> known_placement(storage::ProjectStore& store,
                                                       const storage::TunnelRecord& tunnel,
                                                       storage::RecordId visit_id);

}  // namespace rockface::app
