#pragma once
// A synthetic rock face for the reconstruction tests and benchmark: three
// planar facets of known orientation 10 m in front of two stations 1.6 m
// apart (base/distance 1/6), a 2 m range pole in front of the face and a
// reference line across the middle facet.
#include <array>
#include <cmath>
#include <utility>

#include <Eigen/Core>

#include "camera/synthetic_scene.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"

namespace rockface::testing {

struct FacetTruth {
  double dip_deg, dipdir_deg;
  double x_from, x_to;  // East extent of the facet, metres
};

inline const std::array<FacetTruth, 3>& synthetic_facets() {
  static const std::array<FacetTruth, 3> f{
      {{62, 215, -4.2, -1.4}, {72, 180, -1.4, 1.4}, {58, 140, 1.4, 4.2}}};
  return f;
}

inline Eigen::Vector3d facet_normal(const FacetTruth& f) {
  return geometry::plane_normal_deg(f.dip_deg, f.dipdir_deg);
}

// All facets pass through the line y = 10, z = 0.5 at their x-centre.
inline double facet_y(const FacetTruth& f, double x, double z) {
  const Eigen::Vector3d n = facet_normal(f);
  const double xc = 0.5 * (f.x_from + f.x_to);
  return 10.0 - (n.x() * (x - xc) + n.z() * (z - 0.5)) / n.y();
}

// width x height images; the focal length keeps the field of view.
inline camera::SyntheticScene synthetic_face(int width = 1200, int height = 800,
                                             bool distortion = false, double noise = 0) {
  camera::SyntheticScene s;
  for (const FacetTruth& f : synthetic_facets()) {
    camera::SyntheticPatch p;
    p.id = "facet";
    for (auto [x, z] : {std::pair{f.x_from, -2.5}, {f.x_to, -2.5}, {f.x_to, 3.5}, {f.x_from, 3.5}})
      p.polygon.emplace_back(x, facet_y(f, x, z), z);
    s.patches.push_back(p);
  }
  const double scale = width / 1200.0;
  s.camera.width = width;
  s.camera.height = height;
  s.camera.fx = s.camera.fy = 1100 * scale;
  s.camera.cx = 0.5 * (width - 1) + 3.2 * scale;
  s.camera.cy = 0.5 * (height - 1) - 2.1 * scale;
  if (distortion) s.camera.distortion = {-0.09, 0.03, 0.0004, -0.0003, 0.0};
  s.effects.distortion = distortion;
  s.effects.noise_sigma = noise;
  s.effects.blur_px = noise > 0 ? 0.6 : 0.0;
  s.stations[0] = {{-0.8, 0.0, 0.6}, {0.3, 10.0, 0.4}};
  s.stations[1] = {{0.8, 0.1, 0.5}, {-0.3, 10.0, 0.4}};
  s.range_pole = camera::SyntheticRangePole{{0.6, 7.0, -1.3}, 2.0, 0.25};
  const FacetTruth& mid = synthetic_facets()[1];
  s.reference_line = {{Eigen::Vector3d(-1.0, facet_y(mid, -1.0, 1.8), 1.8),
                       Eigen::Vector3d(1.0, facet_y(mid, 1.0, 2.2), 2.2)}};
  s.texture_seed = 11;
  return s;
}

}  // namespace rockface::testing
