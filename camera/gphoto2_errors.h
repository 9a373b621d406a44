#pragma once
// libgphoto2 result codes turned into messages a geologist understands.
#include <string>

#include "camera/camera_error.h"

namespace rockface::camera {

// `action` says what rockface was doing, e.g. "downloading DSC_0012.JPG".
CameraError gphoto2_error(int code, const std::string& action);

}  // namespace rockface::camera
