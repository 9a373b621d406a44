#pragma once
// What `rockface replay` does with each shot of the mock camera: decode it,
// and keep its EXIF as the project's key/value settings.
#include <map>
#include <string>

#include <opencv2/core.hpp>

#include "camera/camera.h"

namespace rockface::app {

// BGR image; throws InputError naming the file when it cannot be decoded.
cv::Mat decode_shot(const camera::CapturedFile& file, const std::string& label);

std::map<std::string, std::string> exif_map(const camera::ExifInfo& exif);

}  // namespace rockface::app
