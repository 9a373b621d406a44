#include "ui/platform/frame_pacer.h"

#include <thread>

namespace rockface::ui {

FramePacer::FramePacer(double frames_per_second)
    : period_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(1.0 / frames_per_second))),
      next_(std::chrono::steady_clock::now() + period_) {}

void FramePacer::wait() {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) {
    std::this_thread::sleep_until(next_);
    next_ += period_;
  } else {
    // A long frame does not earn a burst of fast ones after it.
    next_ = now + period_;
  }
}

}  // namespace rockface::ui
