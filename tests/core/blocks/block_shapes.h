#pragma once
// Blocks of known shape for tests: prisms over polygons (given by vertices
// and faces) and boxes from half-spaces.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/construction.h"

namespace rockface::blocks::test {

struct Shape {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<FaceInput> faces;
};

// Prism over a counter-clockwise (seen from above) polygon in the plane
// z = z0, up to z = z0 + height. Vertices: bottom 0..n-1, top n..2n-1.
inline Shape prism(const std::vector<Eigen::Vector2d>& polygon, double z0, double height) {
  Shape s;
  const int n = static_cast<int>(polygon.size());
  for (const auto& p : polygon) s.vertices.emplace_back(p.x(), p.y(), z0);
  for (const auto& p : polygon) s.vertices.emplace_back(p.x(), p.y(), z0 + height);
  FaceInput bottom{0, "bottom", PlaneKind::Joint, std::nullopt, {}};
  for (int k = n - 1; k >= 0; --k) bottom.loop.push_back(k);
  FaceInput top{1, "top", PlaneKind::FreeFace, std::nullopt, {}};
  for (int k = 0; k < n; ++k) top.loop.push_back(n + k);
  s.faces = {bottom, top};
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    s.faces.push_back(FaceInput{2 + k,
                                "side" + std::to_string(k),
                                PlaneKind::FreeFace,
                                std::nullopt,
                                {k, k1, n + k1, n + k}});
  }
  return s;
}

inline std::vector<Eigen::Vector2d> rectangle(double a, double b) {
  return {{0, 0}, {a, 0}, {a, b}, {0, b}};
}

// L-shaped polygon: the square [0, 2 a] x [0, 2 a] without its corner
// (a, 2 a] x (a, 2 a]; area 3 a^2.
inline std::vector<Eigen::Vector2d> l_shape(double a) {
  return {{0, 0}, {2 * a, 0}, {2 * a, a}, {a, a}, {a, 2 * a}, {0, 2 * a}};
}

inline Polyhedron build(const Shape& s, const std::string& id = "B",
                        const Eigen::Vector3d& datum = Eigen::Vector3d::Zero()) {
  return build_block_from_faces(id, s.vertices, s.faces, datum);
}

// Half-space with the block on `side` of the plane through `point` with
// upward normal `normal`.
inline HalfSpaceInput halfspace(int index, const std::string& name, PlaneKind kind,
                                const Eigen::Vector3d& normal, const Eigen::Vector3d& point,
                                geometry::HalfSpace side) {
  HalfSpaceInput h;
  h.index = index;
  h.name = name;
  h.kind = kind;
  h.plane.normal = normal.normalized();
  h.plane.offset = h.plane.normal.dot(point);
  h.side = side;
  return h;
}

// The box [0, a] x [0, b] x [0, c] + origin as six half-spaces.
inline std::vector<HalfSpaceInput> box_halfspaces(
    double a, double b, double c, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero()) {
  using geometry::HalfSpace;
  const Eigen::Vector3d far = origin + Eigen::Vector3d(a, b, c);
  return {halfspace(0, "x0", PlaneKind::Joint, Eigen::Vector3d::UnitX(), origin, HalfSpace::Upper),
          halfspace(1, "x1", PlaneKind::Joint, Eigen::Vector3d::UnitX(), far, HalfSpace::Lower),
          halfspace(2, "y0", PlaneKind::Joint, Eigen::Vector3d::UnitY(), origin, HalfSpace::Upper),
          halfspace(3, "y1", PlaneKind::Joint, Eigen::Vector3d::UnitY(), far, HalfSpace::Lower),
          halfspace(4, "z0", PlaneKind::Joint, Eigen::Vector3d::UnitZ(), origin, HalfSpace::Upper),
          halfspace(5, "z1", PlaneKind::FreeFace, Eigen::Vector3d::UnitZ(), far, HalfSpace::Lower)};
}

}  // namespace rockface::blocks::test
