#include "core/mechanics/contact_points.h"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "core/blocks/triangulation.h"
#include "core/common/error.h"

namespace rockface::mechanics {

void joint_frame(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2) {
  // The axis least aligned with n gives a well-conditioned cross product.
  Eigen::Vector3d a = Eigen::Vector3d::UnitX();
  if (std::abs(n.y()) < std::abs(n(0)) && std::abs(n.y()) <= std::abs(n.z()))
    a = Eigen::Vector3d::UnitY();
  else if (std::abs(n.z()) < std::abs(n(0)))
    a = Eigen::Vector3d::UnitZ();
  t1 = a.cross(n).normalized();
  t2 = n.cross(t1);
}

std::vector<ContactPoint> contact_points(const blocks::Polyhedron& block, int density) {
  if (density < 1 || density > 1000)
    throw InputError("analysis.contact_density",
                     std::to_string(density) + " is outside [1, 1000] sub-divisions per edge");
  std::vector<ContactPoint> out;
  const auto& x = block.vertices();
  const double n = density;
  for (int f = 0; f < static_cast<int>(block.faces().size()); ++f) {
    const int p = block.faces()[f].plane;
    const blocks::BlockPlane& bp = block.planes()[p];
    if (bp.kind != blocks::PlaneKind::Joint) continue;
    ContactPoint proto;
    proto.plane = p;
    proto.normal = bp.inward_normal();
    joint_frame(proto.normal, proto.t1, proto.t2);
    for (const blocks::Triangle& t : blocks::triangulate_face(block, f)) {
      const Eigen::Vector3d& a = x[t[0]];
      const Eigen::Vector3d e1 = (x[t[1]] - a) / n, e2 = (x[t[2]] - a) / n;
      const double sub_area = 0.5 * e1.cross(e2).norm();
      // Sub-triangles of the barycentric grid: "upright" (i, j), (i+1, j),
      // (i, j+1) and "inverted" (i+1, j), (i+1, j+1), (i, j+1).
      for (int i = 0; i < density; ++i)
        for (int j = 0; i + j < density; ++j) {
          ContactPoint c = proto;
          c.area = sub_area;
          c.position = a + (i + 1.0 / 3) * e1 + (j + 1.0 / 3) * e2;
          out.push_back(c);
          if (i + j + 1 < density) {
            c.position = a + (i + 2.0 / 3) * e1 + (j + 2.0 / 3) * e2;
            out.push_back(c);
          }
        }
    }
  }
  return out;
}

}  // namespace rockface::mechanics
