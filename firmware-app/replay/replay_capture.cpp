#include "firmware-app/replay/replay_capture.h"

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

}  // namespace rockface::app
