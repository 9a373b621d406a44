#pragma once
// Faces for the facet tests and benchmark, on the lattice of folded_face.h:
// a stepped face whose steps are the exposed faces of two joint sets (a
// sawtooth of strips alternately parallel to set A, dip / dip direction
// (dip, d), and set B, (dip, 360 - d), meeting in ridges), and a flat wall
// (one plane: a sprayed or dressed face with no joints).
#include <cmath>

#include <Eigen/Core>

#include "core/geometry/orientation.h"
#include "tests/support/folded_face.h"

namespace rockface::test {

struct SteppedTruth {
  double dip = 60, dipdir = 220;  // set A; set B is (dip, 360 - dipdir)
  double strip = 0.75;            // m, East width of each strip
  Eigen::Vector3d normal_a() const { return geometry::plane_normal_deg(dip, dipdir); }
  Eigen::Vector3d normal_b() const { return geometry::plane_normal_deg(dip, 360 - dipdir); }
  // Normal spacing of either set: from one A strip to the next the face
  // crosses one B strip, which moves it 2 |n_x| strip along the normal.
  double spacing() const { return 2 * strip * std::abs(normal_a().x()); }
};

// Strips from x = -half_width to half_width m about 10 m north of the
// camera, z from z_from to z_to. The ridges are the sets' intersection
// lines, which (symmetric dip directions) keep a constant x: each strip is
// an x-range of its plane.
inline FoldedFace stepped_face(const SteppedTruth& truth, int width = 800, int height = 600,
                               double depth_sigma = 0, int lattice_step = 2,
                               double half_width = 4.5, double z_from = -2.0, double z_to = 2.5) {
  FoldedFace f;
  f.z_from = z_from;
  f.z_to = z_to;
  const Eigen::Vector3d a = truth.normal_a(), b = truth.normal_b();
  double x = -half_width, y = 10.0;
  for (int i = 0; x < half_width - 1e-9; ++i) {
    const Eigen::Vector3d n = i % 2 == 0 ? a : b;
    geometry::Plane p;
    p.normal = n;
    p.offset = n.dot(Eigen::Vector3d(x, y, 0.0));
    const double to = std::min(half_width, x + truth.strip);
    f.facets.push_back({p, x, to});
    y -= n.x() * (to - x) / n.y();
    x = to;
  }
  look_at_lattice(f, width, height, depth_sigma, lattice_step);
  return f;
}

// One plane (dip, dipdir) through (0, 10, 0.5), 9 m wide.
inline FoldedFace flat_wall(double dip, double dipdir, int width = 800, int height = 600,
                            double depth_sigma = 0, int lattice_step = 2) {
  FoldedFace f;
  f.facets.push_back({plane_through(dip, dipdir, {0.0, 10.0, 0.5}), -4.5, 4.5});
  look_at_lattice(f, width, height, depth_sigma, lattice_step);
  return f;
}

}  // namespace rockface::test
