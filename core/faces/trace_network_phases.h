#pragma once
// The seven phases of TraceNetwork::build, in the order it runs them, and the
// working types they hand on to each other. Internal to core/faces: only the
// trace_network*.cpp files include it. Each phase is a function of its own
// so that it can be read, tested and changed alone; build() only threads the
// data through them.
#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/faces/free_surface.h"
#include "core/faces/trace_network.h"
#include "core/faces/trace_plane.h"

namespace rockface::faces::network_phases {

// A trace's straight stretch on one patch: p + t u, t in [t0, t1] (2D, patch frame).
struct Segment {
  int patch = -1;
  int group = -1;
  Eigen::Vector2d p = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::UnitX();
  double t0 = 0, t1 = 0;
  bool free0 = false, free1 = false;  // a marked end (may be extended), not a patch edge
  int on_edge = -1;                   // patch edge it was laid onto
  bool alive = true;
  std::vector<std::pair<double, int>> points;  // (parameter, point) on it
  double length() const { return t1 - t0; }
  Eigen::Vector2d at(double t) const { return p + t * u; }
};

// Where stretch a (at parameter s) meets stretch b or a patch edge.
struct Hit {
  int patch = -1;
  int a = -1;
  double s = 0;
  int b = -1;         // segment index, or -1 when the other is a patch edge
  int edge = -1;      // patch edge index when b == -1
  double t = 0;       // parameter on b (or on the patch edge)
  Eigen::Vector2d x;  // 2D point
  bool kept = true;
};

// The stretches of the mapped traces and the plane group of each trace
// (one group per mapped trace, in input order; Segment::group indexes them).
struct Stretches {
  std::vector<Segment> segments;
  std::vector<PlaneGroup> groups;
};

// The vertices of the map and, for every candidate point (Segment::points),
// the vertex it became.
struct Vertices {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> of_candidate;
};

// The order of the half-edges around every vertex (AroundVertex) and the
// position of each half-edge in the order of its origin.
struct VertexOrder {
  std::vector<AroundVertex> around;
  std::vector<int> slot;
};

inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Distance from x to the segment ab and the parameter (0..|ab|) of its foot.
inline double distance_to_segment(const Eigen::Vector3d& x, const Eigen::Vector3d& a,
                                  const Eigen::Vector3d& b, double& param) {
  const Eigen::Vector3d d = b - a;
  const double len = d.norm();
  param = std::clamp((x - a).dot(d) / (len * len), 0.0, 1.0) * len;
  return (a + d * (param / len) - x).norm();
}

// The indices of the segments on each patch.
std::vector<std::vector<int>> segments_by_patch(const std::vector<Segment>& segments,
                                                size_t patch_count);

// 1. Planes and straight stretches per patch: each trace's joint plane, cut
// with every patch the trace touches, limited to the marked part (carried to
// the patch edge where the marking goes on to the next patch). Traces left
// out get a note; mapped[i] says which made it.
Stretches trace_stretches(const FreeSurface& surface, const std::vector<TraceInput>& traces,
                          double tolerance, double slack, std::vector<bool>& mapped,
                          std::vector<std::string>& notes);

// 2. A stretch that runs along a patch edge (within the tolerance) is laid
// onto that edge.
void lay_onto_patch_edges(std::vector<Segment>& segments, const FreeSurface& surface,
                          double tolerance, double slack);

// 3. Stretches that run together are one (a trace marked in pieces), and
// traces of one joint that meet on one plane are one discontinuity. Returns
// the merged plane groups; Segment::group is renumbered to index them.
std::vector<PlaneGroup> merge_stretches(std::vector<Segment>& segments,
                                        const std::vector<PlaneGroup>& groups,
                                        const std::vector<std::vector<int>>& by_patch,
                                        const std::vector<TraceInput>& traces,
                                        const FreeSurface& surface, const NetworkOptions& options,
                                        std::vector<std::string>& notes);

// 4. Crossings of stretches with each other and with patch edges; a marked
// end is extended to the nearest one ahead of it within the tolerance, never
// further. Returns every crossing, Hit::kept saying which are used.
std::vector<Hit> crossings_and_extensions(std::vector<Segment>& segments,
                                          const std::vector<std::vector<int>>& by_patch,
                                          const FreeSurface& surface, double tolerance,
                                          double slack);

// 5. Vertices: patch corners, crossings and stretch ends closer than the
// tolerance become one. Adds the candidate points to Segment::points.
Vertices merge_vertices(std::vector<Segment>& segments, const std::vector<Hit>& hits,
                        const FreeSurface& surface, double tolerance, double slack);

// 6. Edges: every stretch between two vertices (vertex_of: the vertex of
// each candidate point, from merge_vertices), and the patch edges. Throws
// InputError when two patches run along a shared edge in the same direction.
std::vector<NetworkEdge> network_edges(std::vector<Segment>& segments,
                                       const std::vector<int>& vertex_of,
                                       const std::vector<Eigen::Vector3d>& vertices,
                                       const FreeSurface& surface, double tolerance,
                                       const std::vector<PlaneGroup>& groups,
                                       std::vector<std::string>& notes);

// 7. The half-edges around each vertex, counter-clockwise seen from the open
// side, unfolding the patches that meet there.
VertexOrder order_around_vertices(const std::vector<Eigen::Vector3d>& vertices,
                                  const std::vector<NetworkEdge>& edges,
                                  const FreeSurface& surface);

}  // namespace rockface::faces::network_phases
