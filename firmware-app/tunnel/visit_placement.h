#pragma once
// A visit's place in the tunnel, found from its 3D image once the image lies
// in the project frame: the face's chainage is where rays along the axis
// meet it (face_front.h; the median of their hits), else the part of the
// surface farthest in the drive direction; the offset and height are of the
// surface within 0.3 m of the face. How the image came into the project frame
// says how the visit was placed: monitoring targets with survey coordinates
// (ground control, with their residuals) or the chainage the geologist typed
// for the range pole plus the compass line.
#include <optional>
#include <string>

#include "core/tunnel/alignment.h"
#include "firmware-app/tunnel/visit_surface.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::app {

// The typed placement of the range pole (scene `tunnel.placement`, or the
// tablet's form): its lower target at a chainage, offset and height above
// the axis. Returns the target centre, datum-relative.
Eigen::Vector3d typed_pole_position(const tunnel::Alignment& alignment, double chainage,
                                    double offset, double height);

// `typed`: a note saying how the pole's place was given ("chainage 112.00
// typed"); empty when the pole's position was surveyed. Throws InputError
// naming the visit when its surface lies off the alignment.
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
