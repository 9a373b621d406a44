#pragma once
// The tablet's frames at most a display's rate, whatever the platform's
// buffer swap does: a swap that does not wait for the display (Mesa's
// software renderer may not) would draw a screen made in a millisecond (the
// Capture screen) hundreds of times a second and take a core from the
// worker that makes the pairs' 3D images beside it. Drawn back to back, the
// headless session's frames made a 24 Mpx pair's 3D image 3-4 times slower
// (issue 45: tools/bench/capture_frames_bench.cpp). Under Xvfb the window's
// swap already held the frames back (27 % of a core on the Project screen
// with and without the pacer); sixty frames a second is what the eye and a
// finger's drag need.
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
