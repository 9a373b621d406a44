#include "core/blocks/mass_properties.h"

#include <cmath>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/blocks/triangulation.h"
#include "core/common/error.h"

namespace rockface::blocks {

double face_area(const Polyhedron& block, int f) {
  // Newell's vector area: exact for any planar polygon, convex or not.
  const auto& loop = block.faces()[f].loop;
  const auto& x = block.vertices();
  Eigen::Vector3d area2 = Eigen::Vector3d::Zero();
  for (size_t k = 1; k + 1 < loop.size(); ++k)
    area2 += (x[loop[k]] - x[loop[0]]).cross(x[loop[k + 1]] - x[loop[0]]);
  return 0.5 * area2.norm();
}

Eigen::Vector3d face_centroid(const Polyhedron& block, int f) {
  const auto& x = block.vertices();
  const Eigen::Vector3d n = block.face_outward_normal(f);
  const Eigen::Vector3d& o = x[block.faces()[f].loop[0]];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0;
  for (const Triangle& t : triangulate_face(block, f)) {
    const double a = 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(n);
    sum += a * ((x[t[0]] - o) + (x[t[1]] - o) + (x[t[2]] - o)) / 3.0;
    area += a;
  }
  return o + sum / area;
}

MassProperties mass_properties(const Polyhedron& block, double density) {
  if (!(density > 0) || !std::isfinite(density))
    throw InputError("block " + block.id(),
                     "density must be positive, got " + std::to_string(density));
  MassProperties mp;
  const auto& x = block.vertices();
  const Triangulation tri = triangulate(block);

  // Volume and centroid: tetrahedra from vertex 0 to every surface triangle,
  // signed by orientation (those outside a non-convex block cancel).
  const Eigen::Vector3d& p0 = x[0];
  double v6 = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();  // 24 x first moment about p0
  for (const Triangle& t : tri.triangles) {
    const Eigen::Vector3d a = x[t[0]] - p0, b = x[t[1]] - p0, c = x[t[2]] - p0;
    const double d = a.dot(b.cross(c));
    v6 += d;
    first += d * (a + b + c);
  }
  mp.volume = v6 / 6.0;
  mp.centroid = p0 + first / (4.0 * v6);
  mp.mass = density * mp.volume;

  // Second moments about the centroid: tetrahedra from the centroid. For a
  // tetrahedron (0, a, b, c) of volume V, the integral of r r^T is
  // V / 20 (a a^T + b b^T + c c^T + s s^T), s = a + b + c.
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const Triangle& t : tri.triangles) {
    const Eigen::Vector3d a = x[t[0]] - mp.centroid, b = x[t[1]] - mp.centroid,
                          c = x[t[2]] - mp.centroid;
    const double vol = a.dot(b.cross(c)) / 6.0;
    const Eigen::Vector3d s = a + b + c;
    second += vol / 20.0 *
              (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  mp.inertia = density * (second.trace() * Eigen::Matrix3d::Identity() - second);
  mp.inertia = 0.5 * (mp.inertia + mp.inertia.transpose()).eval();

  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(mp.inertia);
  mp.principal_moments = es.eigenvalues();
  mp.principal_axes = es.eigenvectors();
  if (mp.principal_axes.determinant() < 0) mp.principal_axes.col(2) *= -1;

  mp.face_areas.resize(block.faces().size());
  mp.plane_areas.assign(block.planes().size(), 0.0);
  for (int f = 0; f < static_cast<int>(block.faces().size()); ++f) {
    mp.face_areas[f] = face_area(block, f);
    mp.plane_areas[block.faces()[f].plane] += mp.face_areas[f];
  }
  return mp;
}

}  // namespace rockface::blocks
