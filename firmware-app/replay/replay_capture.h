#pragma once
// What `rockface replay` does with each shot of the mock camera: decode it.
// (Its EXIF goes to the project as camera::exif_fields.)
#include <string>

#include <opencv2/core.hpp>

#include "camera/camera.h"

namespace rockface::app {

// BGR image; throws InputError naming the file when it cannot be decoded.
cv::Mat decode_shot(const camera::CapturedFile& file, const std::string& label);

}  // namespace rockface::app
