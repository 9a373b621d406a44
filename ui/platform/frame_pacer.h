#pragma once
// The tablet's frames at most a display's rate. On Mesa's software renderer
// the buffer swap does not wait for the display, so a screen drawn in a
// millisecond (the Capture screen) was drawn a thousand times a second,
// taking a core from the worker that makes the pairs' 3D images beside it
// (issue 45: tools/bench/capture_frames_bench.cpp). Sixty frames a second
// is what the eye and a finger's drag need.
#include <chrono>

namespace rockface::ui {

class FramePacer {
 public:
  explicit FramePacer(double frames_per_second = 60);
  // Sleeps out what is left of this frame's period (nothing when the frame
  // took longer), then starts the next period.
  void wait();

 private:
  std::chrono::steady_clock::duration period_;
  std::chrono::steady_clock::time_point next_;
};

}  // namespace rockface::ui
