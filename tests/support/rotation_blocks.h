#pragma once
// Test blocks for rotational kinematics: convex blocks from half-spaces
// (through core/blocks, as the analysis builds them) and blocks given by
// hand as corners and face loops.
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/construction.h"
#include "core/kinematics/rotation_input.h"

namespace rockface::test_rotation {

// A plane of a test block: the block lies on the side `inward` points to.
struct Side {
  std::string name;
  bool joint = true;
  Eigen::Vector3d inward;  // any length
  Eigen::Vector3d point;   // a point on the plane (absolute)
};

inline blocks::HalfSpaceInput halfspace(const Side& s, int index) {
  blocks::HalfSpaceInput h;
  h.index = index;
  h.name = s.name;
  h.kind = s.joint ? blocks::PlaneKind::Joint : blocks::PlaneKind::FreeFace;
  // geometry::Plane wants the upward normal; the side says where the block is.
  Eigen::Vector3d n = s.inward.normalized();
  const bool up = n.z() > 0 || (n.z() == 0 && (n.y() > 0 || (n.y() == 0 && n.x() > 0)));
  h.side = up ? geometry::HalfSpace::Upper : geometry::HalfSpace::Lower;
  if (!up) n = -n;
  h.plane.normal = n;
  h.plane.offset = n.dot(s.point);
  return h;
}

// The convex block of the half-spaces, as a polyhedron (datum-relative).
inline blocks::Polyhedron convex_polyhedron(
    const std::string& id, const std::vector<Side>& sides,
    const Eigen::Vector3d& datum = Eigen::Vector3d::Zero()) {
  std::vector<blocks::HalfSpaceInput> hs;
  for (size_t i = 0; i < sides.size(); ++i) {
    Side s = sides[i];
    s.point -= datum;
    hs.push_back(halfspace(s, static_cast<int>(i)));
  }
  auto built = blocks::build_convex_block(id, hs, Eigen::Vector3d::Zero());
  if (built.outcome != blocks::ConvexOutcome::Bounded || !built.polyhedron)
    throw std::runtime_error("test block " + id + " is not a bounded convex block");
  // Rebuild with the datum so that absolute coordinates come back in reports.
  std::vector<blocks::BlockPlane> planes = built.polyhedron->planes();
  std::vector<blocks::FaceLoop> loops;
  for (const auto& f : built.polyhedron->faces()) loops.push_back({f.plane, f.loop});
  return blocks::Polyhedron::assemble(id, datum, planes, built.polyhedron->vertices(), loops);
}

inline kinematics::RotationInput convex_block(const std::string& id,
                                              const std::vector<Side>& sides) {
  return kinematics::rotation_input(convex_polyhedron(id, sides));
}

// Index of the corner at x (the construction orders corners its own way).
inline int corner_at(const kinematics::RotationInput& in, const Eigen::Vector3d& x) {
  for (size_t v = 0; v < in.vertices.size(); ++v)
    if ((in.vertices[v] - x).norm() < 1e-9 * (1 + x.norm())) return static_cast<int>(v);
  throw std::runtime_error("no corner at the given point");
}

// A tetrahedron A B D E given by hand: faces ABD, ABE, ADE are joints J1,
// J2, J3 and BDE is the free face F1 (loops oriented outward here, normals
// from the corners).
inline kinematics::RotationInput tetrahedron(const std::string& id, const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b, const Eigen::Vector3d& d,
                                             const Eigen::Vector3d& e) {
  kinematics::RotationInput in;
  in.block = id;
  in.vertices = {a, b, d, e};
  const Eigen::Vector3d centroid = (a + b + d + e) / 4;
  const std::vector<std::array<int, 3>> tri = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  const std::vector<std::string> names = {"J1", "J2", "J3", "F1"};
  for (int f = 0; f < 4; ++f) {
    auto [i, j, k] = tri[f];
    Eigen::Vector3d n = (in.vertices[j] - in.vertices[i]).cross(in.vertices[k] - in.vertices[i]);
    std::vector<int> loop = {i, j, k};
    if (n.dot(centroid - in.vertices[i]) > 0) {
      std::swap(loop[1], loop[2]);  // the outward loop runs the other way
    } else {
      n = -n;
    }
    in.planes.push_back({names[f], f < 3, n.normalized()});
    in.faces.push_back({f, loop});
  }
  return in;
}

}  // namespace rockface::test_rotation
