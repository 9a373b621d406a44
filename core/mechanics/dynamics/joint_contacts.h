#pragma once
// Where a moving rigid block touches the rock on its joints.
//
// The rock's side of each joint plane of the block is the block's own face
// on that plane as it was before failure (its "joint surface"): beyond the
// face's edges lies either the excavation (a free face's edge) or the
// neighbouring joint's rock, which that joint's own contacts stand for.
// Rock and block are rigid, so a pressure distribution over the overlap of
// the block's face with the joint surface is equivalent to non-negative
// forces at the overlap's corners, and those are the contacts:
//   - corners of the block's face over the joint surface (material points
//     of the block against the fixed plane; the block's corners on the
//     joint face are contact_points.h's density-0 set);
//   - corners of the joint surface under the block's face (points of the
//     rock against the block's moving face: the block tips over them);
//   - crossings of the face's edges with the surface's edges.
// A face sliding in its plane keeps its overlap's corners; a block turning
// about an edge or a corner keeps only the corners on it; a face that has
// left its plane or slid off the surface has none.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/blocks/polyhedron.h"

namespace rockface::mechanics {

// The rock's side of one joint plane of the block.
struct JointSurface {
  int plane = -1;                                     // index into the polyhedron's planes()
  std::string name;                                   // "J1"
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, from the rock into the block
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();   // a point of the plane (datum-relative)
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();  // in-plane axes
  std::vector<std::vector<Eigen::Vector2d>> polygons;  // the block's faces on the plane, at rest
  std::vector<std::vector<int>> loops;                 // their vertex indices
  // Per polygon, per edge k (corner k to k + 1): the plane of the face across it.
  std::vector<std::vector<std::string>> edge_planes;
  double friction = 0;  // tan(friction angle) while sliding
};

// A rigid placement of the block: its centroid moved by u, turned by q
// about the centroid.
struct BlockPose {
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
};

enum class ContactKind { BlockCorner, RockCorner, EdgeCrossing };

struct JointContact {
  int surface = -1;  // index into the surfaces
  ContactKind kind = ContactKind::BlockCorner;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // where it acts now (datum-relative)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, the direction it pushes the block
  double gap = 0;                                     // m, > 0 open, < 0 penetrating
  // Block corners slide over a fixed plane; the rock's corners and edge
  // crossings are fixed points under a turning face (its normal turns).
  bool on_fixed_plane() const { return kind == ContactKind::BlockCorner; }
  int vertex = -1;  // the block's corner (BlockCorner) or the surface's corner (RockCorner)
};

class JointContacts {
 public:
  // friction_deg: per polyhedron plane, the friction angle (degrees) of
  // each joint plane while sliding (others ignored).
  JointContacts(const blocks::Polyhedron& block, const Eigen::Vector3d& centroid,
                const std::vector<double>& friction_deg);

  // Contacts in support (over the joint surface) whose gap is below
  // gap_limit (m), at the pose.
  std::vector<JointContact> contacts(const BlockPose& pose, double gap_limit) const;
  // Current position of the block's vertex v.
  Eigen::Vector3d vertex(const BlockPose& pose, int v) const {
    return centroid_ + pose.u + pose.q * arms_[v];
  }
  const std::vector<JointSurface>& surfaces() const { return surfaces_; }
  const std::vector<Eigen::Vector3d>& arms() const { return arms_; }  // vertex - centroid, at rest
  const Eigen::Vector3d& centroid() const { return centroid_; }
  double length() const { return length_; }  // the block's diameter (block_diameter.h)

 private:
  // Whether a point of space (in the block's frame at rest) that lies
  // `depth` behind the face on `plane` is inside the block and nearest to
  // that face: then it came in through it.
  bool entered_through(const Eigen::Vector3d& y, int plane, double depth) const;

  std::vector<JointSurface> surfaces_;
  std::vector<Eigen::Vector3d> arms_;
  std::vector<Eigen::Vector3d> plane_inward_;  // per polyhedron plane, at rest
  std::vector<double> plane_offset_;           // inward . x on the plane
  Eigen::Vector3d centroid_;
  double length_ = 1;
};

// Whether p lies in the polygon or within tol of its boundary.
bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p,
                    double tol);

}  // namespace rockface::mechanics
