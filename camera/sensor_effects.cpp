#include "camera/sensor_effects.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"

namespace rockface::camera {

SensorNoise::SensorNoise(const SyntheticSensor& sensor)
    : electrons_per_grey_(sensor.full_well_e * sensor.base_iso / sensor.iso / 255.0),
      read_noise_e_(sensor.read_noise_e) {}

double SensorNoise::apply(double grey, cv::RNG& rng) const {
  const double full = 255.0 * electrons_per_grey_;
  const double electrons = std::clamp(grey * electrons_per_grey_, 0.0, full);
  const double noisy =
      electrons + std::sqrt(electrons) * rng.gaussian(1.0) + read_noise_e_ * rng.gaussian(1.0);
  return std::min(noisy, full) / electrons_per_grey_;
}

cv::Mat jpeg_round_trip(const cv::Mat& bgr, int quality) {
  std::vector<uint8_t> bytes;
  if (!cv::imencode(".jpg", bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, quality}))
    throw Error("synthetic camera: JPEG encoding at quality " + std::to_string(quality) +
                " failed");
  cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_COLOR);
  if (decoded.empty()) throw Error("synthetic camera: JPEG decoding failed");
  return decoded;
}

}  // namespace rockface::camera
