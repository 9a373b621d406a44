#pragma once
// Waiting for a triggered shot's files, bounded (issue 42). libgphoto2's
// own capture call (ptp2's gp_camera_capture) waits for the new object
// without a bound when the body makes none, and its wait loops poll no
// cancel (gp_context_cancel is polled only within large data transfers):
// so rockface triggers the shot (gp_camera_trigger_capture) and reads the
// camera's events itself, each wait bounded by the timeout it passes.
#include <functional>
#include <string>
#include <vector>

#include "camera/camera.h"

namespace rockface::camera {

struct ShotWait {
  int capture_timeout_ms = 30000;      // for the shot's first file
  int file_after_complete_ms = 10000;  // for it after the body's "capture complete"
  int follow_up_ms = 3000;             // for its follow-up files (a RAW) after the first
};

// The camera's paths of the shot's files, in the order the camera named
// them, from `next_event(timeout_ms)` (the camera's next event within
// timeout_ms, a timeout event if none). Throws CameraError: no_file when
// none came in time (naming how long rockface waited), card_full on PTP's
// StoreFull event.
std::vector<std::string> wait_for_shot_files(const std::function<CameraEvent(int)>& next_event,
                                             const ShotWait& wait);

}  // namespace rockface::camera
