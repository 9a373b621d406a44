#pragma once
// From a disparity map of the rectified pair to the lattice surface mesh in
// the left camera's frame (model units: the base is 1).
#include <opencv2/core.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/matching/dense_matching.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::photogrammetry {

struct LatticeOptions {
  int step = 1;                     // one vertex every `step` rectified pixels
  double max_jump_px = 1.5;         // disparity step between lattice neighbours (per step) that
                                    // breaks the surface (occlusion edge): no triangle across it
  double max_depth_in_bases = 500;  // farther points are noise (intersection angle < 0.1 deg)
};

// rectified_left: the rectified left image (colours); left: the original
// camera (texture coordinates point into the original photograph).
SurfaceMesh triangulate_lattice(const DisparityMap& disparity, const Rectification& rect,
                                const cv::Mat& rectified_left, const CameraIntrinsics& left,
                                const LatticeOptions& options, Progress& progress);

}  // namespace rockface::photogrammetry
