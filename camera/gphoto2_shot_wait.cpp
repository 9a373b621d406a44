#include "camera/gphoto2_shot_wait.h"

#include <algorithm>
#include <chrono>

#include <gphoto2/gphoto2-result.h>

#include "camera/camera_error.h"
#include "camera/gphoto2_errors.h"
#include "core/common/number_format.h"

namespace rockface::camera {

namespace {

using Clock = std::chrono::steady_clock;

int ms_until(Clock::time_point end) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - Clock::now());
  return static_cast<int>(std::max<long long>(left.count(), 0));
}

}  // namespace

std::vector<std::string> wait_for_shot_files(const std::function<CameraEvent(int)>& next_event,
                                             const ShotWait& wait) {
  const auto start = Clock::now();
  const auto deadline = start + std::chrono::milliseconds(wait.capture_timeout_ms);
  auto until = deadline;
  std::vector<std::string> files;
  bool complete = false;
  while (files.empty() && ms_until(until) > 0) {
    const CameraEvent e = next_event(ms_until(until));
    if (e.kind == CameraEvent::Kind::file_added) {
      files.push_back(e.detail);
    } else if (e.kind == CameraEvent::Kind::capture_complete && !complete) {
      // Over without a file yet: some bodies send the file after (once
      // written to the card), but not without end.
      complete = true;
      until =
          std::min(deadline, Clock::now() + std::chrono::milliseconds(wait.file_after_complete_ms));
    } else if (e.detail.rfind("PTP Event 400a", 0) == 0) {
      // PTP's StoreFull event (0x400A), which ptp2 hands on unnamed.
      throw gphoto2_error(GP_ERROR_NO_SPACE, "Taking a picture",
                          "the card ran full during the capture (PTP event StoreFull)");
    }
  }
  if (files.empty()) {
    const auto waited = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start);
    throw CameraError(
        CameraError::Kind::no_file,
        "Taking a picture: the camera took no picture or returned no file within " +
            format_fixed(static_cast<double>(waited.count()) / 1000, 1, " s") +
            (complete ? " (it said the capture was over)" : "") +
            ": check that it can focus on the face (or is on manual focus), that the lens cap is "
            "off and the card is in, then shoot again; pictures already downloaded are safe");
  }
  // The RAW of a RAW+JPEG shot follows as another "file added".
  const auto drain_end = Clock::now() + std::chrono::milliseconds(wait.follow_up_ms);
  for (;;) {
    const int left = ms_until(drain_end);
    const CameraEvent e = next_event(left);
    if (e.kind == CameraEvent::Kind::file_added) files.push_back(e.detail);
    if (e.kind == CameraEvent::Kind::timeout || left <= 0) break;
  }
  return files;
}

}  // namespace rockface::camera
