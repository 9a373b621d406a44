#pragma once
// The tablet UI without a screen: a surfaceless EGL context (Mesa's software
// renderer where no GPU is), frames rendered into a framebuffer, touch
// events from a script or a test, and the frames' pixels as screenshots.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "ui/platform/egl_context.h"
#include "ui/platform/framebuffer.h"
#include "ui/tablet_app.h"
#include "ui/touch_input.h"
#include "ui/ui_script.h"

namespace rockface::ui {

class HeadlessSession {
 public:
  HeadlessSession(UiOptions options, FieldServices services, int width, int height);
  ~HeadlessSession();

  // Builds and renders one frame.
  void frame();
  // Frames until the worker is idle and its outcome taken (a finished task
  // may start the next, e.g. loading the model it saved).
  void settle();
  // The last frame's pixels (BGR, top row first).
  cv::Mat screenshot() const { return target_.read_bgr(); }

  // Input, each followed by the frames ImGui needs to see it.
  void tap(float x, float y);
  // Taps the centre of a target drawn in the last frame; throws InputError
  // (naming `where`) when there is none or it is disabled.
  void tap(const std::string& label, const std::string& where = "tap");
  void drag(Eigen::Vector2f from, Eigen::Vector2f to, int frames);
  void pinch(Eigen::Vector2f centre, float from, float to, int frames);

  // Runs a script step; screenshots go to `dir` as NAME.png.
  void run(const ScriptStep& step, const std::filesystem::path& dir, const std::string& where);

  TabletApp& app() { return *app_; }
  AppState& state() { return app_->state(); }
  TouchInput& input() { return input_; }
  std::string renderer() const { return egl_.describe(); }

 private:
  void frames_until_input_consumed();
  EglContext egl_;
  Framebuffer target_;
  TouchInput input_;
  std::unique_ptr<TabletApp> app_;
  int width_, height_;
};

struct ScriptRun {
  std::vector<std::filesystem::path> screenshots;
  std::string status;  // the status bar at the end
  std::string renderer;
};

// Runs a whole script. Throws InputError for a bad step; the project keeps
// whatever the steps before it saved.
ScriptRun run_ui_script(const UiOptions& options, const FieldServices& services,
                        const UiScript& script, const std::filesystem::path& screenshots_dir);

}  // namespace rockface::ui
