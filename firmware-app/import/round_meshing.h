#pragma once
// A scan of a whole round (walls, roof and invert all around the tunnel's
// axis, and the face at its end) folds over any plane: a 2.5D mesh over its
// best plane keeps one side and drops the rest. When the project has a
// tunnel, such a cloud is meshed on the tunnel's developed view instead:
// each point near the design outline at (chainage, arc length of the design
// outline where the ray from the profile's ray centre through it meets the
// outline), both in metres of excavated surface, where the walls do not
// fold; the points well inside the outline (the face) over their own best
// plane. Holes stay holes (cloud_meshing.h's edge test); the invert's seam
// (arc length 0 = perimeter) is closed by meshing a band of the outline's
// start again past its end.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/surface/cloud_meshing.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"

namespace rockface::app {

struct RoundMesh {
  // Indices into the whole cloud; every triangle faces the tunnel's inside
  // (counter-clockwise seen from the axis, the face's seen from behind it).
  std::vector<std::array<int, 3>> triangles;
  std::size_t wall_points = 0, face_points = 0, unused_points = 0;
  double median_spacing = 0;
  // The walls' scatter normal to their surface (cloud_noise.h, on the
  // developed view); none when too few cells hold enough points.
  std::optional<double> noise_sigma_m;
  // Where the view looks at: the face's centre (else the walls' front end),
  // and the unit direction back along the drive, toward a viewer behind it.
  Eigen::Vector3d view_centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d toward_viewer = Eigen::Vector3d::UnitZ();
  std::string words;  // how it was meshed, for the import's note
};

// `points`: datum-relative, as `alignment` (the project's tunnel at the
// project's datum); `colours`: empty or one per point. None when the cloud
// is not a round: fewer than 75 % of its points within 0.7 to 1.6 times the
// design radius toward them, or those covering less than half of the way
// round the outline, or less than 1 m of chainage; the cloud is then as it
// was. A round's points and colours are reordered in place, the walls'
// first and the face's after them (the triangles index the new order): its
// 10 million points are meshed without a copy of them (issue 43's peak).
std::optional<RoundMesh> mesh_round(std::vector<Eigen::Vector3d>& points,
                                    std::vector<std::array<std::uint8_t, 3>>& colours,
                                    const tunnel::Alignment& alignment,
                                    const tunnel::DesignProfile& profile);

}  // namespace rockface::app
