#pragma once
// What rotational kinematics needs to know about a block: its corners, its
// faces, and for each face's plane whether it is a joint (the rock on the
// other side stops the block) or a free face (nothing there), with the
// block-side normal. Built from a blocks::Polyhedron for the analysis, or
// directly (tests, blocks found by other means).
//
// The corner checks only ever look at corners: the displacement of a point
// X of a face, u x (X - p) . n, is linear in X, so it is non-negative over a
// convex face polygon when it is at the face's corners, and a non-convex
// face's corners are its extreme points too.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rockface::blocks {
class Polyhedron;
}

namespace rockface::kinematics {

struct RotationPlane {
  std::string name;   // plane id ("J1"), for reports
  bool joint = true;  // false: a free face, which constrains nothing
  Eigen::Vector3d inward_normal = Eigen::Vector3d::UnitZ();  // unit, from the plane into the block
};

struct RotationFace {
  int plane = -1;         // index into RotationInput::planes
  std::vector<int> loop;  // vertex indices, counter-clockwise seen from outside
};

struct RotationInput {
  std::string block;  // block id, for messages
  std::vector<RotationPlane> planes;
  std::vector<Eigen::Vector3d> vertices;  // datum-relative
  std::vector<RotationFace> faces;
};

// An edge of the block with the two planes meeting there.
struct RotationEdge {
  std::array<int, 2> vertices{};  // ascending
  std::array<int, 2> planes{};    // the planes of the two faces sharing it
};

// Derived once per block: what meets where.
struct RotationTopology {
  std::vector<std::vector<int>> vertex_planes;  // distinct planes of the faces around each vertex
  std::vector<RotationEdge> edges;              // every edge, sorted by vertices
  double size = 0;                              // bounding-box diagonal: the length scale
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // mean of the corners (a point inside)

  bool has_joint(const RotationInput& in, int v) const;
  bool has_free_face(const RotationInput& in, int v) const;
  // A static point: a corner on the boundary between joints and free faces.
  bool is_static_point(const RotationInput& in, int v) const {
    return has_joint(in, v) && has_free_face(in, v);
  }
  // An edge where a joint face meets a free face.
  bool is_boundary_edge(const RotationInput& in, const RotationEdge& e) const {
    return in.planes[e.planes[0]].joint != in.planes[e.planes[1]].joint;
  }
};

// Checks indices, normals and the edge structure (every edge shared by
// exactly two faces) and derives the topology. Throws rockface::InputError
// naming the block and the face, plane or vertex that is wrong.
RotationTopology rotation_topology(const RotationInput& in);

// The polyhedron's planes (joints and free faces by their kind, block-side
// normals), vertices (datum-relative, same indices) and faces.
RotationInput rotation_input(const blocks::Polyhedron& block);

}  // namespace rockface::kinematics
