#include "camera/rock_texture.h"

#include <algorithm>
#include <cmath>

namespace rockface::camera {

namespace {

// Integer hash (a murmur3-style finaliser): lattice values must be
// reproducible bit for bit on every machine, so no std:: random engines.
inline uint32_t hash(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// One hash per lattice point: the coordinates are spread by large odd
// multipliers before mixing, so neighbouring points share no low bits.
inline float lattice(int64_t i, int64_t j, int64_t k, uint32_t salt) {
  const uint32_t h =
      hash(static_cast<uint32_t>(i) * 0x8DA6B343U ^ static_cast<uint32_t>(j) * 0xD8163841U ^
           static_cast<uint32_t>(k) * 0xCB1AB31FU ^ salt);
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);  // [0, 1)
}

// Quintic fade: continuous second derivative, so no visible lattice creases.
inline double fade(double t) {
  return t * t * t * (t * (t * 6 - 15) + 10);
}

}  // namespace

float RockTexture::value_noise(double x, double y, double z, uint32_t octave) const {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto i = static_cast<int64_t>(fx), j = static_cast<int64_t>(fy),
             k = static_cast<int64_t>(fz);
  const double u = fade(x - fx), v = fade(y - fy), w = fade(z - fz);
  const uint32_t salt = hash(seed_ * 0x27d4eb2dU + octave);
  const double c000 = lattice(i, j, k, salt), c100 = lattice(i + 1, j, k, salt);
  const double c010 = lattice(i, j + 1, k, salt), c110 = lattice(i + 1, j + 1, k, salt);
  const double c001 = lattice(i, j, k + 1, salt), c101 = lattice(i + 1, j, k + 1, salt);
  const double c011 = lattice(i, j + 1, k + 1, salt), c111 = lattice(i + 1, j + 1, k + 1, salt);
  const double x00 = c000 + u * (c100 - c000), x10 = c010 + u * (c110 - c010);
  const double x01 = c001 + u * (c101 - c001), x11 = c011 + u * (c111 - c011);
  const double y0 = x00 + v * (x10 - x00), y1 = x01 + v * (x11 - x01);
  return static_cast<float>(y0 + w * (y1 - y0));
}

float RockTexture::albedo(const Eigen::Vector3d& p, double footprint_m) const {
  // Persistence 0.85: fine octaves keep much of the contrast of coarse ones,
  // as in crystalline rock, which gives dense matching detail at every scale.
  double sum = 0, norm = 0, amplitude = 1;
  double wavelength = kCoarsestWavelength;
  uint32_t octave = 0;
  while (wavelength >= kFinestWavelength) {
    // Full weight from 4 footprints per wavelength, none below 2 (Nyquist).
    const double weight = std::clamp(wavelength / footprint_m / 2.0 - 1.0, 0.0, 1.0);
    if (weight <= 0) break;
    const double s = 1.0 / wavelength;
    // Each octave is offset so lattice points of different octaves do not align.
    const double n = value_noise(p.x() * s + 17.3 * octave, p.y() * s - 9.1 * octave,
                                 p.z() * s + 4.7 * octave, octave);
    sum += weight * amplitude * (n - 0.5);
    norm += amplitude;
    amplitude *= 0.85;
    wavelength *= 0.5;
    ++octave;
  }
  // A sum of independent octaves concentrates near the mean; stretch it to
  // the contrast of weathered rock and clamp the rare extremes.
  const double contrast = norm > 0 ? 0.75 * sum / std::sqrt(norm) : 0.0;
  return static_cast<float>(std::clamp(0.5 + contrast, 0.15, 0.85));
}

}  // namespace rockface::camera
