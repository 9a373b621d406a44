#pragma once
// Drives the tablet UI frame by frame with touch input: what scripts and
// tests do, on a window (the device) or headless. A platform implements
// frame() (build, render and show one frame, feeding its own events first)
// and screenshot(); the taps, drags, pinches and script steps are the same
// everywhere.
#include <filesystem>
#include <string>

#include <opencv2/core.hpp>

#include "ui/app/app_state.h"
#include "ui/app/ui_script.h"
#include "ui/widgets/touch_input.h"

namespace rockface::ui {

class UiDriver {
 public:
  virtual ~UiDriver() = default;

  virtual void frame() = 0;
  // The last frame's pixels (BGR, top row first).
  virtual cv::Mat screenshot() const = 0;
  virtual AppState& state() = 0;
  TouchInput& input() { return input_; }

  // Frames until the worker and the queue of 3D images are idle and their
  // outcomes taken (a finished task may start the next, e.g. loading the
  // model it saved).
  void settle();
  // Input, each followed by the frames ImGui needs to see it.
  void tap(float x, float y);
  // Taps the centre of a target drawn in the last frame, first dragging
  // its panels until it is in view as a finger would (bring_into_view);
  // throws InputError (naming `where`) when there is none, it is disabled,
  // or no drag brings it into view.
  void tap(const std::string& label, const std::string& where = "tap");
  // One finger down at `from`, moved to `to` over `frames` frames, up: on a
  // panel that scrolls, a drag scrolls it (ui/widgets/widgets_scroll.h); on the 3D
  // image it turns the model.
  void drag(Eigen::Vector2f from, Eigen::Vector2f to, int frames);
  // Drags the panels a target lies in (innermost first, each inside its
  // part on the screen, never from a control that takes drags itself) until
  // the whole target shows, or as much as its panel can show; the drags
  // made. Throws InputError naming `where` when there is no such target or
  // no drag moves it into view.
  int bring_into_view(const std::string& label, const std::string& where = "scroll");
  void pinch(Eigen::Vector2f centre, float from, float to, int frames);

  // Runs a script step; screenshots go to `dir` as NAME.png.
  void run(const ScriptStep& step, const std::filesystem::path& dir, const std::string& where);

 protected:
  TouchInput input_;

 private:
  void frames_until_input_consumed();
};

// What a script cost on each screen: the taps made there and the time
// spent there (waiting for the worker included), in the order the screens
// were first used.
struct ScreenUse {
  std::string screen;
  int taps = 0;
  double seconds = 0;
};

struct ScriptRun {
  std::vector<std::filesystem::path> screenshots;
  std::string status;  // the status bar at the end
  std::vector<ScreenUse> screens;
};

// Runs a whole script on a driver. Throws InputError for a bad step; the
// project keeps whatever the steps before it saved.
ScriptRun run_ui_script(UiDriver& driver, const UiScript& script,
                        const std::filesystem::path& screenshots_dir);

}  // namespace rockface::ui
