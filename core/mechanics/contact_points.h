#pragma once
// Contact points on the joint faces of a block: where the joint law acts.
// Each joint face is triangulated (core/blocks/triangulation.h) and every
// triangle is split into density^2 equal sub-triangles; a contact sits at
// each sub-triangle's centroid and carries its area. The midpoint rule on
// the sub-triangles integrates tractions that vary linearly across a
// sub-triangle exactly; the density knob trades the resolution of the
// contact stress distribution (toppling, rotation) against time.
// Free faces carry no contacts: they are open to the excavation.
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"

namespace rockface::mechanics {

struct ContactPoint {
  int plane = -1;                                      // index into the polyhedron's planes()
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // datum-relative, initial position
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // unit, from the joint into the block
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();       // unit shear axes of the joint frame,
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitY();       // (t1, t2, normal) right-handed
  double area = 0;                                     // m^2
};

// density >= 1 sub-divisions per triangle edge; throws InputError
// ("analysis.contact_density") otherwise.
std::vector<ContactPoint> contact_points(const blocks::Polyhedron& block, int density);

// A unit vector pair completing n to a right-handed frame (t1, t2, n),
// chosen from n alone so that it is the same for every face of a plane.
void joint_frame(const Eigen::Vector3d& n, Eigen::Vector3d& t1, Eigen::Vector3d& t2);

}  // namespace rockface::mechanics
