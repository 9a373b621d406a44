#pragma once
// Touch input mapped onto ImGui 1.86's mouse input.
//
// ImGui 1.86 has no input queue: it reads io.MousePos and io.MouseDown once
// per frame, so a finger that goes down and up between two frames would be
// lost. TouchInput queues the events and hands them to ImGui one change of
// the primary finger per frame (a tap becomes a press frame and a release
// frame, after a frame that only moves the pointer there). One finger is the mouse's left button:
// taps press buttons, drags orbit the model. Two fingers are a gesture (pinch to zoom, move both to
// pan) that the model view reads from gesture(); while two fingers are
// down the mouse button is released, so a pinch never presses a button.
#include <deque>
#include <map>

#include <Eigen/Core>

struct ImGuiIO;

namespace rockface::ui {

struct TouchEvent {
  enum class Kind { down, move, up };
  Kind kind = Kind::down;
  int finger = 0;      // stays the same from down to up
  float x = 0, y = 0;  // pixels, origin top left
};

// What two fingers did since the last frame.
struct TouchGesture {
  bool active = false;  // two or more fingers are down
  float pinch = 1;      // ratio of finger spread to last frame's (> 1: fingers apart, zoom in)
  Eigen::Vector2f pan = Eigen::Vector2f::Zero();  // pixels the fingers' centre moved
  // Where the pointer (the primary finger) is, to the fraction of a pixel:
  // ImGui floors io.MousePos to whole pixels, up to a pixel up and left of
  // the finger (a pick on the 3D image wants the finger's own place).
  Eigen::Vector2f pointer = Eigen::Vector2f::Zero();
};

class TouchInput {
 public:
  void push(const TouchEvent& event);
  // A mouse wheel (desktop test runs) as a pinch: steps > 0 zoom in.
  void push_wheel(float steps) { wheel_ += steps; }
  // Consumes the events of one frame and writes them into io.
  void apply(ImGuiIO& io);
  const TouchGesture& gesture() const { return gesture_; }
  bool idle() const { return queue_.empty(); }

 private:
  void update_gesture();
  std::deque<TouchEvent> queue_;
  std::map<int, Eigen::Vector2f> fingers_;  // down now
  Eigen::Vector2f mouse_ = {-1, -1};
  bool mouse_down_ = false;
  float wheel_ = 0;
  TouchGesture gesture_;
  float last_spread_ = 0;
  Eigen::Vector2f last_centre_ = Eigen::Vector2f::Zero();
};

}  // namespace rockface::ui
