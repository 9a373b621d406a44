#include "ui/platform/headless_session.h"

namespace rockface::ui {

namespace {
// Headless frames advance ImGui's clock by a tablet's frame time, so that
// double-tap and drag timing behave as on the device.
constexpr float kFrameSeconds = 1.0f / 60;
}  // namespace

HeadlessSession::HeadlessSession(UiOptions options, FieldServices services, int width, int height)
    : egl_(EglContext::surfaceless()),
      target_(width, height),
      app_(std::make_unique<TabletApp>(std::move(options), services)),
      width_(width),
      height_(height) {
  frame();
}

HeadlessSession::~HeadlessSession() {
  app_.reset();
}  // before the GL context goes

void HeadlessSession::frame() {
  app_->build_frame(input_, width_, height_, kFrameSeconds);
  target_.bind();
  if (app_->draw()) ++frames_drawn_;
  Framebuffer::unbind();
}

}  // namespace rockface::ui
