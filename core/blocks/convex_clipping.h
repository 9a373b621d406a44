#pragma once
// A convex polyhedron cut down half-space by half-space, keeping its faces
// as loops: the topology follows from one inside / on / outside decision per
// vertex and plane, so it is consistent however close corners come (four
// or more planes through one surveyed point, a joint a hair's breadth from
// another). Corners of planes that meet within the tolerance become one
// vertex instead of a ridge of numerically distinct ones.
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace rockface::blocks {

// A face of the clipped solid: its loop counter-clockwise seen from
// outside and the plane it lies on (an index into the half-spaces; negative
// for a face of the starting box).
struct ClippedFace {
  int plane = -1;
  std::vector<int> loop;
};

struct ClippedSolid {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<ClippedFace> faces;
};

// The box [lo, hi] cut by the half-spaces inward[i] . x >= offset[i] (unit
// inward normals) in order. A vertex within `on_plane` (metres) of a plane
// is on it: it is neither cut off nor does it make a new corner. Vertices
// closer than `merge` (metres) at the end are one. A solid with no faces
// when the cuts leave nothing with volume; nothing when the tolerance leaves
// no consistent one (a cut whose section does not close into one loop).
std::optional<ClippedSolid> clip_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                     const std::vector<Eigen::Vector3d>& inward,
                                     const std::vector<double>& offset, double on_plane,
                                     double merge);

}  // namespace rockface::blocks
