#include "ui/widgets/touch_input.h"

#include <imgui.h>

#include <cmath>

namespace rockface::ui {

namespace {
// One wheel step of a desktop mouse zooms as much as spreading two fingers
// by 10 %.
constexpr float kWheelStepPinch = 1.1f;
}  // namespace

void TouchInput::push(const TouchEvent& event) {
  queue_.push_back(event);
}

void TouchInput::apply(ImGuiIO& io) {
  gesture_.pinch = 1;
  gesture_.pan = Eigen::Vector2f::Zero();
  // Take events until the primary finger's button state changed once: ImGui
  // must see every press and every release in a frame of its own.
  bool button_changed = false;
  while (!queue_.empty() && !button_changed) {
    const TouchEvent e = queue_.front();
    const Eigen::Vector2f p(e.x, e.y);
    // A finger lands anywhere, a mouse glides there: move the pointer onto
    // the spot one frame before pressing, so widgets that want to be
    // hovered before they are pressed see it hover.
    if (e.kind == TouchEvent::Kind::down && fingers_.empty() && mouse_ != p) {
      mouse_ = p;
      break;
    }
    queue_.pop_front();
    switch (e.kind) {
      case TouchEvent::Kind::down:
        fingers_[e.finger] = p;
        break;
      case TouchEvent::Kind::move:
        fingers_[e.finger] = p;
        break;
      case TouchEvent::Kind::up:
        fingers_.erase(e.finger);
        break;
    }
    const bool one_finger = fingers_.size() == 1;
    const bool want_down = one_finger && !gesture_.active;
    if (one_finger) mouse_ = fingers_.begin()->second;
    if (e.kind == TouchEvent::Kind::up && fingers_.empty()) mouse_ = p;
    if (want_down != mouse_down_) {
      mouse_down_ = want_down;
      button_changed = true;
    }
    update_gesture();
  }
  if (fingers_.empty()) gesture_.active = false;
  if (wheel_ != 0) {
    gesture_.pinch *= std::pow(kWheelStepPinch, wheel_);
    wheel_ = 0;
  }
  gesture_.pointer = mouse_;
  io.MousePos = ImVec2(mouse_.x(), mouse_.y());
  io.MouseDown[0] = mouse_down_;
}

void TouchInput::update_gesture() {
  if (fingers_.size() < 2) {
    // The gesture lasts until every finger is up, so lifting one finger of
    // a pinch does not turn the other into a drag or a tap.
    if (fingers_.empty()) gesture_.active = false;
    last_spread_ = 0;
    return;
  }
  auto it = fingers_.begin();
  const Eigen::Vector2f a = it->second, b = (++it)->second;
  const float spread = (a - b).norm();
  const Eigen::Vector2f centre = (a + b) / 2;
  if (gesture_.active && last_spread_ > 0) {
    gesture_.pinch *= spread / last_spread_;
    gesture_.pan += centre - last_centre_;
  }
  gesture_.active = true;
  last_spread_ = spread;
  last_centre_ = centre;
}

}  // namespace rockface::ui
