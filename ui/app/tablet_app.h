#pragma once
// The tablet application: one full-screen ImGui window per frame with the
// screen tabs on top, the current screen, and a status bar with the worker's
// progress and a cancel button at the bottom. TabletApp owns the ImGui
// context and its GLES 3 renderer; the platform (a window or the headless
// runner) feeds touch input and says where the frame goes.
#include "ui/app/app_state.h"
#include "ui/platform/drawn_frame.h"

namespace rockface::ui {

class TabletApp {
 public:
  // The GL context must be current; creates the ImGui context.
  TabletApp(UiOptions options, FieldServices services);
  TabletApp(const TabletApp&) = delete;
  TabletApp& operator=(const TabletApp&) = delete;
  ~TabletApp();

  // Builds one frame of width x height pixels (the model view renders into
  // its own framebuffer here), then draw() renders it into the framebuffer
  // the caller bound in between (the window's or the headless one). draw()
  // draws nothing and returns false when the frame would draw the pixels
  // the framebuffer already holds from the last one drawn (DrawnFrame);
  // draw_again() makes the next frame drawn whatever it holds (a new
  // framebuffer, an exposed window).
  void build_frame(TouchInput& input, int width, int height, float seconds_since_last);
  bool draw();
  void draw_again() { drawn_.forget(); }

  AppState& state() { return state_; }
  const AppState& state() const { return state_; }

 private:
  void build();
  void draw_tabs();
  void draw_status_bar();
  void keep_model_loaded();

  AppState state_;
  DrawnFrame drawn_;
};

}  // namespace rockface::ui
