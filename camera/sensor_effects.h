#pragma once
// The sensor and the file of the synthetic camera (SyntheticEffects.sensor,
// jpeg_quality): noise in electrons at an ISO, and the JPEG round trip.
#include <opencv2/core.hpp>

#include "camera/synthetic_scene.h"

namespace rockface::camera {

// Photon shot noise and read noise of a sensor at an ISO, in electrons.
// Full scale (255 grey levels) holds full_well_e * base_iso / iso electrons,
// so the gain is that / 255 electrons per grey level: at ISO 3200 a mid grey
// holds ~600 e- and its shot noise is ~4 % of it.
class SensorNoise {
 public:
  explicit SensorNoise(const SyntheticSensor& sensor);
  // A grey level (the rendered value before quantisation, may exceed 255)
  // with noise: electrons collected (clipped at the full well), shot noise
  // as a Gaussian of variance equal to the electrons (Poisson, which it is
  // to better than a percent above 20 e-), read noise, back to grey levels.
  double apply(double grey, cv::RNG& rng) const;
  double electrons_per_grey() const { return electrons_per_grey_; }

 private:
  double electrons_per_grey_ = 1;
  double read_noise_e_ = 0;
};

// cv::imencode / imdecode at `quality` (1..100): the blocks and ringing of
// a camera's JPEG. Throws Error when OpenCV cannot encode.
cv::Mat jpeg_round_trip(const cv::Mat& bgr, int quality);

}  // namespace rockface::camera
