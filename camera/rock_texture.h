#pragma once
// A rock-like albedo defined in world coordinates: multi-octave value noise
// (fractal Brownian motion) over a 3-D lattice. Because the texture lives on
// the surface and not in the image, both stations of a stereo pair see the
// same pattern, so it matches the way real rock does.
//
// Octaves finer than the pixel footprint are faded out (band limiting), so
// a far or a grazing view shows a smooth average instead of aliasing noise.
#include <cstdint>

#include <Eigen/Core>

namespace rockface::camera {

class RockTexture {
 public:
  explicit RockTexture(unsigned seed) : seed_(seed) {}

  // Albedo in about [0.15, 0.85] at world point p for a pixel footprint of
  // `footprint_m` metres on the surface.
  float albedo(const Eigen::Vector3d& p, double footprint_m) const;

  // Coarsest and finest wavelengths of the fractal, metres.
  static constexpr double kCoarsestWavelength = 0.8;
  static constexpr double kFinestWavelength = 0.0005;

 private:
  float value_noise(double x, double y, double z, uint32_t octave) const;
  unsigned seed_;
};

}  // namespace rockface::camera
