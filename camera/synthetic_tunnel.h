#pragma once
// A synthetic tunnel for the mock camera (beside the other synthetic
// scenes the renderer draws; the scene file's `tunnel.render` becomes one in
// firmware-app/tunnel/rendered_tunnel.h): the excavated surface of a round
// (walls, roof, invert and the face) built from the design profile along
// the alignment, with known over- and underbreak, as the renderer's planar
// patches. The same description gives the truth the profile measurement is
// tested against: the deviation at any (chainage, arc length) and the
// over- / underbreak area of any cross-section.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "camera/synthetic_scene.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"

namespace rockface::camera {

// A smooth bump of the excavated surface off the design line: depth_m along
// the outline's outward normal at its centre (+ overbreak, - underbreak),
// falling to zero at its edges as sin^2 in chainage and in arc length, so
// its volume on a straight wall is depth x length x width / 4.
struct RenderedBreak {
  double chainage_from = 0, chainage_to = 0;  // m, ascending
  double s_from = 0, s_to = 0;                // m of design outline (design_profile.h), ascending
  double depth_m = 0;
};

struct RenderedTunnelSpec {
  double chainage_from = 0;  // the far end of the rendered walls (behind the cameras)
  double face_chainage = 0;  // the face: walls end here, the face closes the section
  double section_m = 0.25;   // facets along the chainage
  double facet_m = 0.1;      // facets along the outline (chord sag on a 3 m arc: 0.4 mm)
  // How far the face's centre bulges toward the cameras (m): the face is a
  // shallow four-sided pyramid, its corners on the walls; 0 = flat.
  double face_relief_m = 0;
  std::vector<RenderedBreak> breaks;
};

// Deviation (m, along the outline's outward normal, + overbreak) of the
// rendered surface at a chainage and arc length: the sum of the breaks.
double rendered_deviation(const RenderedTunnelSpec& spec, double chainage, double s);

// The true over- and underbreak areas (m^2) of the cross-section at a
// chainage between two arc lengths (whole outline by default): the area
// between the design line and the surface displaced along the normal,
// d (1 + kappa d / 2) integrated over s (kappa the outline's curvature, 1/R
// on arcs toward their centre, 0 on lines), sampled every millimetre.
struct SectionTruth {
  double overbreak_m2 = 0, underbreak_m2 = 0;
};
SectionTruth rendered_section_truth(const RenderedTunnelSpec& spec,
                                    const tunnel::DesignProfile& profile, double chainage,
                                    double s_from = 0, double s_to = -1);

// The patches: triangles of walls, roof and invert from chainage_from to the
// face, ids "TUNNEL-<row>-<col>-<k>", and the face (the outline at
// face_chainage: four planar quarters "FACE-1".. "FACE-4", see
// face_relief_m). Datum-relative like the
// alignment's local frame. Throws InputError naming `where` when the range is
// empty or off the alignment.
std::vector<SyntheticPatch> rendered_tunnel_patches(const RenderedTunnelSpec& spec,
                                                    const tunnel::Alignment& alignment,
                                                    const tunnel::DesignProfile& profile,
                                                    const std::string& where);

}  // namespace rockface::camera
