#pragma once
// Is there enough texture on the face to match? Dust haze (Koschmieder:
// the face's contrast times exp(-beta d) under a veil of airlight), too
// little light or a fogged lens leave the rock's texture at a few grey
// levels, where sensor noise and JPEG blocks outweigh it: feature and dense
// matching then find few or wrong correspondences, and the scale and the
// orientations come out wrong or the pair is refused with a message that
// blames the overlap. This check comes first and names the cause.
#include <string>

#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct ImageContrast {
  // Robust level (75th percentile over the frame) of the texture that
  // matching uses: the band of 2 to 8 px wavelengths at 1000 px width, rms
  // in 15 x 15 px windows, with the noise's share taken out. Grey levels.
  double texture_grey = 0;
  double noise_grey = 0;   // sensor noise, rms per pixel (Immerkaer's estimator)
  double bright_grey = 0;  // 90th percentile of the grey levels
  double median_grey = 0;
  double darkest_grey = 0, brightest_grey = 0;
};

ImageContrast measure_contrast(const cv::Mat& image);

// The parts of the measure, for the dense matching's texture check
// (texture_mask.h). All take a grey CV_32F image.
// The texture band: a difference of Gaussians (sigma 1 and 4 px).
cv::Mat band_pass(const cv::Mat& grey_f32);
// How much of a white noise's variance the band-pass keeps (its kernel's
// energy).
double band_pass_noise_gain();
// Sensor noise, rms per pixel (Immerkaer's estimator, the median of its
// responses so that edges and traces do not count).
double sensor_noise_grey(const cv::Mat& grey_f32);

// Below this texture (grey levels rms, noise taken out) the fast preset no
// longer registers the synthetic face (tests/integration/lighting, measured
// by tools/bench/tunnel_lighting_bench.cpp): the face at 10 m keeps 2.5
// grey levels in dust of 40 m visibility and registers (scale within
// 0.7 %), 1.8 in 30 m and loses the pole, 1.4 in 25 m and loses the
// orientation. The limit sits between the last that holds and the first
// that fails.
constexpr double kMinMatchableTexture = 2.0;

// A photograph whose 90th percentile is below this is dark, not veiled:
// haze lifts the dark parts toward the airlight, darkness leaves nine
// pixels in ten below a quarter of full scale.
constexpr double kDarkImage = 64;
// An image whose grey levels all lie within this range is blank (a capped
// lens, a black frame): a few levels of sensor noise at most.
constexpr double kBlankRange = 4;
// Half the photograph at or above this is clipped: JPEG's top levels.
constexpr double kClippedImage = 245;

// Below this ratio of texture to sensor noise the matches are noise:
// measured on the synthetic face at high ISO, a ratio of 3.6 (ISO 12800)
// registers with the scale within 0.8 % and the facets within 0.7 deg, 1.7
// (ISO 51200) came out 2 % in scale and 6 deg in the facets and north
// without any other check objecting; the independent face of
// tests/integration/reconstruct (a darker rock, 3.4 grey levels of texture
// under 1.5 of noise: 2.3) registers within its test's bounds. The limit
// sits between the lowest that holds and the highest that fails.
constexpr double kMinTextureToNoise = 2.0;

// Throws InputError("left image" / "right image", ...) naming the texture,
// the noise and the limit when a photograph has too little texture.
void require_matchable_contrast(const cv::Mat& image, const std::string& which);

}  // namespace rockface::photogrammetry
