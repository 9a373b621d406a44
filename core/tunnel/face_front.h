#pragma once
// Where the face itself stands, read along the tunnel: rays parallel to the
// axis, started behind the face from points well inside the design profile
// (within 70 % of the way from the ray centre to the outline, so they meet
// the face and not a wall), find the face's surface. Their median is the
// face's chainage; their nearest is where the face reaches farthest back
// toward the cameras, which the cross-sections of the round must stay
// short of (a section through the face's bulge would read the face as
// metres of underbreak).
#include <optional>

#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/profile_deviation.h"

namespace rockface::tunnel {

struct FaceFront {
  double median_chainage = 0;
  double nearest_chainage = 0;  // toward the cameras
  int rays = 0, hits = 0;
};

// Rays start at `from_chainage` (behind the face, where the cameras stood
// or the surface starts). A ray whose first triangle has a vertex that is not
// rock (the range pole in front of the face) counts for nothing; the
// surface's per-triangle mask is not read. Nothing when no ray meets rock.
std::optional<FaceFront> face_front(const Alignment& alignment, const DesignProfile& profile,
                                    const SurfaceInput& surface, double from_chainage);

}  // namespace rockface::tunnel
