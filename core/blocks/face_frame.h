#pragma once
// 2-D coordinates of a face's corners in its own plane, with the axes
// (u, w) chosen so that u x w is the outward normal: a loop that runs
// counter-clockwise seen from outside runs counter-clockwise in (u, w).
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"

namespace rockface::blocks {

struct FaceFrame {
  Eigen::Vector3d origin, u, w;
  std::vector<Eigen::Vector2d> corners;  // in loop order
};

FaceFrame face_frame(const Polyhedron& block, int f);

}  // namespace rockface::blocks
