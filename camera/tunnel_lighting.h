#pragma once
// How the synthetic face is lit in a tunnel (SyntheticEffects: flash, lamps,
// wet and shotcrete regions, dust, vignetting): the light model the
// renderer calls per hit when the scene asks for any of these. Without them
// the renderer keeps its own headlamp model, so renders of scenes that ask
// for none stay bit for bit what they were.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "camera/synthetic_scene.h"

namespace rockface::camera {

// A region (wet, shotcrete) prepared for point-in-region tests.
class PreparedRegion {
 public:
  // Throws InputError naming `where` for fewer than 3 points or no area.
  PreparedRegion(const SyntheticRegion& region, const std::string& where);
  // Whether a surface point lies in the region (SyntheticRegion).
  bool contains(const Eigen::Vector3d& q) const;
  // The parts of a straight segment (on the surface) outside the region.
  std::vector<std::array<Eigen::Vector3d, 2>> outside(const Eigen::Vector3d& a,
                                                      const Eigen::Vector3d& b) const;

 private:
  Eigen::Vector2d local(const Eigen::Vector3d& q) const;
  Eigen::Vector3d origin_, normal_, eu_, ev_;
  std::vector<Eigen::Vector2d> polygon_;
  Eigen::Vector2d lo_, hi_;
};

struct PointLight {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double intensity = 1.0;  // full white x m^2
};

// The lights of one station: its flash (at the camera) and the lamps.
class TunnelLights {
 public:
  TunnelLights(const SyntheticEffects& effects, const SyntheticStation& station);
  // Lambertian irradiance at q on a surface with unit normal n (facing the
  // camera), of full white: sum of I cos(incidence) / d^2 over the lights.
  double diffuse(const Eigen::Vector3d& q, const Eigen::Vector3d& n) const;
  // Blinn-Phong lobe: sum of (n.h)^shininess I / d^2 over the lights that
  // light the side of n, h the half vector of the light and `to_camera`.
  double specular(const Eigen::Vector3d& q, const Eigen::Vector3d& n,
                  const Eigen::Vector3d& to_camera, double shininess) const;

 private:
  std::vector<PointLight> lights_;
};

// Blinn-Phong lobe of the default headlamp (a light of unit irradiance at
// `lamp`, no falloff, as the default lighting has none).
double headlamp_specular(const Eigen::Vector3d& q, const Eigen::Vector3d& n,
                         const Eigen::Vector3d& to_camera, const Eigen::Vector3d& lamp,
                         double shininess);

// Vignetting at a ray of normalised (undistorted) image coordinates (x, y):
// 1 - strength (1 - cos^4 theta), at least 0; strength 1 is the cos^4 law.
inline double vignetting_factor(double x, double y, double strength) {
  const double c2 = 1.0 / (1.0 + x * x + y * y);
  return std::max(0.0, 1.0 - strength * (1.0 - c2 * c2));
}

}  // namespace rockface::camera
