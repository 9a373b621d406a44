#pragma once
// libgphoto2 result codes turned into messages a geologist understands.
#include <string>

#include "camera/camera_error.h"

namespace rockface::camera {

// `action` says what rockface was doing, e.g. "downloading DSC_0012.JPG".
// `driver_says` is the camera driver's own text for this failure (its
// context error), which tells apart what one code stands for: libgphoto2's
// ptp2 driver reports a memory card that ran full during a capture as
// GP_ERROR_NO_MEMORY ("Camera memorycard ran full during capture.") and a
// card already full as a bare GP_ERROR ("PTP Store Full"). It ends the
// message, for support.
CameraError gphoto2_error(int code, const std::string& action, const std::string& driver_says = {});

}  // namespace rockface::camera
