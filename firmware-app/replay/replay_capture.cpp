#include "firmware-app/replay/replay_capture.h"

#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"

namespace rockface::app {

cv::Mat decode_shot(const camera::CapturedFile& file, const std::string& label) {
  cv::Mat image;
  try {
    image = cv::imdecode(file.data, cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
  }
  if (image.empty())
    throw InputError(file.saved_path.empty() ? file.camera_path : file.saved_path,
                     label + " image cannot be decoded (corrupt or not an image)");
  return image;
}

std::map<std::string, std::string> exif_map(const camera::ExifInfo& e) {
  std::map<std::string, std::string> m;
  auto put = [&](const char* k, const auto& v) {
    if (v) {
      std::ostringstream s;
      s << *v;
      m[k] = s.str();
    }
  };
  if (!e.make.empty()) m["make"] = e.make;
  if (!e.model.empty()) m["model"] = e.model;
  if (!e.lens.empty()) m["lens"] = e.lens;
  if (!e.datetime.empty()) m["datetime"] = e.datetime;
  put("focal_length_mm", e.focal_length_mm);
  put("f_number", e.f_number);
  put("exposure_time_s", e.exposure_time_s);
  put("iso", e.iso);
  put("flash_fired", e.flash_fired);
  put("focus_distance_m", e.focus_distance_m);
  return m;
}

}  // namespace rockface::app
