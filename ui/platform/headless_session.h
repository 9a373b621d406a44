#pragma once
// The tablet UI without a screen: a surfaceless EGL context (Mesa's software
// renderer where no GPU is), frames rendered into a framebuffer, touch
// events from a script or a test, and the frames' pixels as screenshots.
#include <memory>
#include <string>

#include "ui/app/tablet_app.h"
#include "ui/app/ui_driver.h"
#include "ui/platform/egl_context.h"
#include "ui/platform/framebuffer.h"

namespace rockface::ui {

class HeadlessSession final : public UiDriver {
 public:
  HeadlessSession(UiOptions options, FieldServices services, int width, int height);
  ~HeadlessSession() override;

  void frame() override;
  cv::Mat screenshot() const override { return target_.read_bgr(); }
  AppState& state() override { return app_->state(); }
  std::string renderer() const { return egl_.describe(); }
  // Frames whose draw data were drawn into the framebuffer (a frame that
  // would draw what it holds is not: TabletApp::draw).
  long frames_drawn() const { return frames_drawn_; }
  // The next frame drawn whatever it holds.
  void draw_again() { app_->draw_again(); }

 private:
  EglContext egl_;
  Framebuffer target_;
  std::unique_ptr<TabletApp> app_;
  int width_, height_;
  long frames_drawn_ = 0;
};

}  // namespace rockface::ui
