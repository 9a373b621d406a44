#pragma once
// The trace map as a graph on the free surface. Each trace becomes, on every
// patch it crosses, the straight stretch where its joint plane cuts the patch,
// limited to the part the geologist marked (and carried to the patch edge
// where the marking continues onto the next patch). Then:
//   - stretches of different traces that run together (within the snap
//     tolerance: a trace marked in pieces) become one, and a stretch that
//     runs along a patch edge is laid onto that edge;
//   - a marked end is extended to the nearest trace or patch edge ahead of it
//     when that is within the snap tolerance along the trace, never further;
//   - crossings (with each other and with patch edges), corners and ends
//     closer than the snap tolerance become one vertex;
//   - every stretch between two vertices is an edge; the patch edges are
//     edges too, so that every face of the graph lies on one patch.
// Dangling ends stay in the map; the loop search ignores them.
//
// Around every vertex the edges are ordered counter-clockwise seen from the
// open side. Where patches meet at the vertex each patch's sector is
// unfolded into the next one across their shared edge, so the order is
// consistent across patch edges and corners of the excavation.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/faces/free_surface.h"
#include "core/faces/trace_plane.h"

namespace rockface::faces {

struct NetworkOptions {
  double snap_tolerance = 0.05;        // m
  double orientation_uncertainty = 0;  // radians: planes this close are "the same"
};

// The joint plane shared by traces that the map treats as one discontinuity.
struct PlaneGroup {
  std::string name;         // the first trace's id
  std::vector<int> traces;  // input trace indices, ascending
  TracePlane plane;
  std::optional<TraceJoint> joint;
};

struct NetworkEdge {
  int v0 = -1, v1 = -1;
  // Patches the edge lies on; for a patch-boundary edge, whether the patch's
  // counter-clockwise boundary runs v0 -> v1.
  struct OnPatch {
    int patch = -1;
    bool boundary = false;
    bool forward = true;
  };
  std::vector<OnPatch> patches;
  int group = -1;  // plane group of a trace stretch; -1 for a bare patch edge
  bool patch_boundary() const {
    for (const auto& p : patches)
      if (p.boundary) return true;
    return false;
  }
  bool outline() const;  // boundary of exactly one patch: the edge of the mapped surface
};

struct AroundVertex {
  std::vector<int> half_edges;  // outgoing, counter-clockwise (unfolded angle ascending)
  std::vector<double> angle;    // unfolded angle of each, radians
  double total = 0;             // the full turn around the vertex (2 pi on a flat patch)
  struct Sector {
    int patch = -1;
    double begin = 0, end = 0;  // unfolded angles covered by the patch
  };
  std::vector<Sector> sectors;
};

class TraceNetwork {
 public:
  static TraceNetwork build(const FreeSurface& surface, const std::vector<TraceInput>& traces,
                            const NetworkOptions& options);

  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  const std::vector<NetworkEdge>& edges() const { return edges_; }
  const std::vector<PlaneGroup>& groups() const { return groups_; }
  const std::vector<AroundVertex>& around() const { return around_; }
  // Messages about traces left out, snapped or odd (each names the trace).
  const std::vector<std::string>& notes() const { return notes_; }
  // Input traces that made it into the map (with a plane and a stretch).
  const std::vector<bool>& mapped() const { return mapped_; }
  // The marked points of each input trace (datum-relative), to tell which
  // traces of a merged discontinuity run along a given stretch.
  const std::vector<std::vector<Eigen::Vector3d>>& trace_points() const { return trace_points_; }
  double snap_tolerance() const { return snap_tolerance_; }  // m

  // Half-edge h = 2 e + d runs v0 -> v1 (d = 0) or v1 -> v0 (d = 1).
  int origin(int h) const { return h % 2 == 0 ? edges_[h / 2].v0 : edges_[h / 2].v1; }
  int target(int h) const { return origin(h ^ 1); }
  // Lu's rule: after arriving along h, the outgoing half-edge that turns
  // most to the left (the next one clockwise from the way back), so that
  // the face on the left of h is walked counter-clockwise.
  int next(int h) const;
  // Position of half-edge h in around()[origin(h)].
  int slot(int h) const { return slot_[h]; }

 private:
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<NetworkEdge> edges_;
  std::vector<PlaneGroup> groups_;
  std::vector<AroundVertex> around_;
  std::vector<int> slot_;
  std::vector<std::string> notes_;
  std::vector<bool> mapped_;
  std::vector<std::vector<Eigen::Vector3d>> trace_points_;
  double snap_tolerance_ = 0;
};

}  // namespace rockface::faces
