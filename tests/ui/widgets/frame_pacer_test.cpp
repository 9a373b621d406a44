// The tablet's frame pacing (issue 45): frames at most the display's rate,
// and a long frame not followed by a burst of fast ones. Only lower bounds
// of time are checked (a sleep never ends early); how long a frame takes
// on this machine is the benchmark's business (capture_frames_bench).
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "ui/platform/frame_pacer.h"

namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

TEST(FramePacer, FramesComeAtMostAtItsRate) {
  rockface::ui::FramePacer pacer(100);  // a period of 10 ms
  const auto from = Clock::now();
  for (int i = 0; i < 10; ++i) pacer.wait();
  // Ten periods of 10 ms each: 100 ms at least (sleep_until never wakes early).
  EXPECT_GE(Clock::now() - from, milliseconds(100));
}

TEST(FramePacer, ALongFrameIsNotMadeUpByFastOnes) {
  rockface::ui::FramePacer pacer(100);
  std::this_thread::sleep_for(milliseconds(50));  // a frame five periods long
  pacer.wait();                                   // returns at once: the frame is late
  const auto from = Clock::now();
  for (int i = 0; i < 3; ++i) pacer.wait();
  // The next three frames each wait a whole period (30 ms at least), not
  // nothing to catch up the five periods the long frame took.
  EXPECT_GE(Clock::now() - from, milliseconds(30));
}

}  // namespace
