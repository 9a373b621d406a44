#pragma once
// A block as a closed polyhedron (no holes): the planes that bound it, each
// with the half-space code of the side the block lies on, its vertices, its
// faces as counter-clockwise loops seen from outside, and a half-edge
// structure linking them, so that any face, edge or corner leads to its
// neighbours.
//
// Coordinates are datum-relative (DESIGN.md): vertices() are x - datum(), so
// survey coordinates of 1e6 m lose no precision; absolute_vertex() adds the
// datum back for reports.
//
// A Polyhedron is only ever built validated (closed, consistently oriented
// with outward loops, Euler-Poincare characteristic 2, every face planar
// within tolerance, every vertex a manifold corner): see assemble() and the
// construction functions in core/blocks/construction.h.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/plane.h"

namespace rockface::blocks {

// What a bounding plane is to block theory.
enum class PlaneKind { Joint, FreeFace };

struct BlockPlane {
  int index = -1;    // caller's plane index (scene order: joints, then free faces); -1 none
  std::string name;  // caller's plane id ("J1"), used in messages and reports
  PlaneKind kind = PlaneKind::Joint;
  geometry::Plane plane;  // datum-relative, unit upward normal (geometry::Plane convention)
  geometry::HalfSpace side = geometry::HalfSpace::Upper;  // the half-space the block lies in

  // Unit normal pointing from the plane into the block (the block-side normal).
  Eigen::Vector3d inward_normal() const { return plane.inward_normal(side); }
  Eigen::Vector3d outward_normal() const { return -inward_normal(); }
};

// A directed edge of one face's loop. Loops run counter-clockwise seen from
// outside, so a half-edge's face lies on its left seen from outside.
struct HalfEdge {
  int origin = -1;  // vertex the half-edge leaves
  int face = -1;
  int next = -1, prev = -1;  // within the face's loop
  int twin = -1;             // the opposite half-edge, in the neighbouring face
  int edge = -1;             // the undirected edge it belongs to
};

// An undirected edge: half_edge runs v0 -> v1 in face `left`; its twin runs
// v1 -> v0 in face `right`.
struct Edge {
  int v0 = -1, v1 = -1;
  int half_edge = -1;
  int left = -1, right = -1;  // faces
};

struct Face {
  int plane = -1;         // index into planes()
  std::vector<int> loop;  // vertex indices, counter-clockwise seen from outside
  int half_edge = -1;     // the half-edge leaving loop[0]
};

// Input of assemble(): one loop per face, with the index of its plane.
struct FaceLoop {
  int plane = -1;
  std::vector<int> loop;
};

class Polyhedron {
 public:
  Polyhedron() = default;

  // Builds the half-edge structure and validates. Throws rockface::InputError
  // naming the block and the face / vertex / edge for: a vertex index out of
  // range, a loop with fewer than 3 distinct vertices, a face plane index out
  // of range, an edge used twice in the same direction (inconsistent
  // orientation), an edge with no opposite (not closed), a vertex used by no
  // face or whose faces do not form one fan (not a manifold corner), an Euler
  // characteristic other than 2, a face not planar within
  // `planarity_tolerance` (metres; negative: kFacePlanarityRel x size()), a
  // vertex off its face's plane by more than that, and loops that run
  // clockwise seen from outside (negative volume).
  static Polyhedron assemble(std::string id, const Eigen::Vector3d& datum,
                             std::vector<BlockPlane> planes, std::vector<Eigen::Vector3d> vertices,
                             const std::vector<FaceLoop>& faces, double planarity_tolerance = -1);

  const std::string& id() const { return id_; }
  const Eigen::Vector3d& datum() const { return datum_; }  // absolute position of the origin
  const std::vector<BlockPlane>& planes() const { return planes_; }
  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }  // datum-relative
  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<HalfEdge>& half_edges() const { return half_edges_; }
  const std::vector<Edge>& edges() const { return edges_; }

  Eigen::Vector3d absolute_vertex(int v) const { return vertices_[v] + datum_; }
  // Diagonal of the axis-aligned bounding box: the length scale of the block.
  double size() const { return size_; }

  // The vertex a half-edge arrives at.
  int target(int half_edge) const { return half_edges_[half_edges_[half_edge].next].origin; }
  // The half-edge from vertex a to vertex b, -1 if a and b are not joined.
  int half_edge_between(int a, int b) const;

  // Half-edges, edges and the other face across each edge, of face f, in loop order.
  std::vector<int> face_half_edges(int f) const;
  std::vector<int> face_edges(int f) const;
  std::vector<int> adjacent_faces(int f) const;

  // Around vertex v, counter-clockwise seen from outside, in matching order:
  // the k-th outgoing half-edge belongs to the k-th face and the k-th edge.
  std::vector<int> outgoing_half_edges(int v) const;
  std::vector<int> faces_around_vertex(int v) const;
  std::vector<int> edges_around_vertex(int v) const;
  // The distinct planes (indices into planes()) of the faces around v.
  std::vector<int> planes_at_vertex(int v) const;
  // The faces lying on plane p (several for a non-convex block).
  std::vector<int> faces_on_plane(int p) const;

  // Outward unit normal of face f (of its plane, the side the block is not on).
  Eigen::Vector3d face_outward_normal(int f) const {
    return planes_[faces_[f].plane].outward_normal();
  }
  // Unit direction of edge e from v0 to v1.
  Eigen::Vector3d edge_direction(int e) const;
  // Whether the solid angle inside the block at edge e exceeds 180 degrees.
  bool edge_is_reflex(int e) const;

 private:
  std::string id_;
  Eigen::Vector3d datum_ = Eigen::Vector3d::Zero();
  std::vector<BlockPlane> planes_;
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Face> faces_;
  std::vector<HalfEdge> half_edges_;
  std::vector<Edge> edges_;
  std::vector<int> vertex_half_edge_;  // one half-edge leaving each vertex
  double size_ = 0;
};

}  // namespace rockface::blocks
