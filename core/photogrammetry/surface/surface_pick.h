#pragma once
// The surface point a pick on the left photograph names, read from the 3D
// image around it rather than from its nearest vertex: the plane most of the
// vertices within `radius_px` of the pick agree on (least median of
// squares, then least squares over its inliers), met by the pick's viewing
// ray. A single vertex carries the dense matching's error at that pixel;
// beside a nearer object the matching window spreads the object's disparity
// over the surface behind it (issue 38: the sample heading's compass line
// ended 20 px beside the range pole, its vertex 59 mm too deep at 8 m, and
// the model turned 0.96 deg about the pole: 2-4 cm on the walls 3 m away).
#include <optional>

#include <Eigen/Core>

#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::photogrammetry {

struct SurfacePickOptions {
  // Full-size pixels around the pick: 20 px is ~15 cm of rock at 8 m with
  // fx 800, small beside a face's relief, and holds ~1000 vertices at a
  // lattice step of 1, enough to outvote a smeared strip beside an edge.
  double radius_px = 20;
  int trials = 300;           // random three-vertex planes tried (fixed seed: repeatable)
  double inlier_sigma = 2.5;  // inliers within this many robust sigmas of the plane
};

// The mesh in the frame of the left camera that took `left` (camera at the
// origin, looking along +z). Nothing when fewer than 3 vertices lie within
// the radius; the nearest vertex when the plane is nearly parallel to the
// ray (no intersection to trust).
std::optional<Eigen::Vector3d> surface_point_at_pick(const SurfaceMesh& mesh,
                                                     const Eigen::Vector2d& pixel,
                                                     const CameraIntrinsics& left,
                                                     const SurfacePickOptions& options = {});

}  // namespace rockface::photogrammetry
