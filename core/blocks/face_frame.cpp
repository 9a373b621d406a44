#include "core/blocks/face_frame.h"

#include <cmath>

#include <Eigen/Geometry>

namespace rockface::blocks {

FaceFrame face_frame(const Polyhedron& block, int f) {
  FaceFrame fr;
  const Eigen::Vector3d n = block.face_outward_normal(f);
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  fr.u = helper.cross(n).normalized();
  fr.w = n.cross(fr.u);
  const auto& loop = block.faces()[f].loop;
  fr.origin = block.vertices()[loop[0]];
  for (int v : loop) {
    const Eigen::Vector3d d = block.vertices()[v] - fr.origin;
    fr.corners.emplace_back(d.dot(fr.u), d.dot(fr.w));
  }
  return fr;
}

}  // namespace rockface::blocks
