#pragma once
// The closed loops of the trace map (Lu's rule), each the free-surface part
// of one candidate block.
//
// Every face of the trace network lies on one patch (patch edges are edges
// of the network) or outside the surface. Faces are walked with Lu's rule:
// arriving at a vertex, go on along the stretch with the sharpest turn to
// the left, seen from the open side, so bounded faces run counter-clockwise.
// Faces that only a patch edge separates are one region (a loop may cross
// patch edges: blocks at an edge or corner of the excavation); faces that a
// trace separates are not. A region that reaches the edge of the mapped
// surface is not closed by traces: it joins the unbounded outer region and
// is no block. An island of traces inside a face is a hole in its region.
#include <vector>

#include "core/faces/free_surface.h"
#include "core/faces/trace_network.h"

namespace rockface::faces {

struct SurfaceFace {
  std::vector<int> half_edges;  // counter-clockwise for a bounded face
  int patch = -1;               // -1: outside the surface
  double area = 0;  // signed, in the patch plane (m^2); <= 0 for the outside of an island
};

struct SurfaceRegion {
  std::vector<int> faces;
  std::vector<int> patches;             // the patches it covers, ascending
  std::vector<std::vector<int>> loops;  // trace half-edges around it; loops[0] the outer one
  std::vector<int> groups;              // plane groups of its loop stretches, first-seen order
  std::vector<int> traces;              // input trace indices, in loop order, once each
  double area = 0;                      // m^2 of free surface
};

class SurfaceLoops {
 public:
  static SurfaceLoops find(const TraceNetwork& network, const FreeSurface& surface);

  const std::vector<SurfaceFace>& faces() const { return faces_; }
  // The closed regions only (the unbounded one is excluded).
  const std::vector<SurfaceRegion>& regions() const { return regions_; }
  // Region of each face; -1 for the unbounded outer region.
  const std::vector<int>& face_region() const { return face_region_; }
  const std::vector<int>& half_edge_face() const { return half_edge_face_; }

 private:
  std::vector<SurfaceFace> faces_;
  std::vector<SurfaceRegion> regions_;
  std::vector<int> face_region_;
  std::vector<int> half_edge_face_;
};

// Winding number of the closed polygon around p (2D).
int winding_number(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace rockface::faces
