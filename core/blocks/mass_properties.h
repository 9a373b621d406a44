#pragma once
// Volume, mass, centroid, inertia and face areas of a block, from its vertex
// coordinates by signed tetrahedra: central projection from a block vertex
// for volume and centroid, from the centroid for the inertia tensor. Works for
// non-convex blocks without decomposition (the signed volumes of the
// projected tetrahedra cancel outside the block). Datum-relative throughout.
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"

namespace rockface::blocks {

struct MassProperties {
  double volume = 0;                                   // m^3
  double mass = 0;                                     // kg
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // datum-relative
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // kg m^2, about the centroid, global axes
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();   // ascending
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();  // columns, right-handed
  std::vector<double> face_areas;                                // m^2, per face
  std::vector<double> plane_areas;  // m^2, per plane: the sum of its faces
};

// density in kg/m^3. Throws rockface::InputError for a non-positive density.
MassProperties mass_properties(const Polyhedron& block, double density);

// Area of face f (m^2) and its area-weighted centroid (datum-relative).
double face_area(const Polyhedron& block, int f);
Eigen::Vector3d face_centroid(const Polyhedron& block, int f);

}  // namespace rockface::blocks
