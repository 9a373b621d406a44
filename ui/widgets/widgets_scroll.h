#pragma once
// Drag to scroll, as on a tablet: a finger dragged on a panel that scrolls
// (a side panel, a table, an open choice's list) moves its content with the
// finger. ImGui 1.86 scrolls only by the wheel and the scroll bar; on a
// touch screen a 9 mm bar takes the room of the buttons it scrolls to.
//
// A press is a tap until the finger has moved `slop` (2 mm at the tablet's
// DPI: a fingertip wobbles by about 1 mm). Past it the press becomes a
// scroll: the control the finger went down on loses the press (it is
// neither pressed on release nor held), so a drag never both scrolls and
// presses. Controls that take drags themselves (a slider, the 3D image that
// turns or takes a trace's taps, a proposal's handle) say so with
// takes_drags(): a drag begun on them stays theirs and never scrolls.
//
// The scroll bar is a thin position indicator, not a touch target: a press
// on it is taken from ImGui's scroll bar (which would jump the content to
// the finger) and becomes a drag of the panel like any other press there.
#include <optional>
#include <set>

#include <imgui.h>

struct ImGuiWindow;

namespace rockface::ui {

// Slop between a tap and a drag, mm: a gloved fingertip rolls by about 1 mm
// when it presses; 2 mm is past that and well under a target's 9 mm.
constexpr float kDragSlopMm = 2;
// Width of the scroll bar as drawn (a position indicator), pixels at scale 1.
constexpr float kScrollIndicatorPx = 8;

class DragScroll {
 public:
  // Call once a frame after ImGui::NewFrame() and before any window is
  // begun (TouchTargets::begin_frame does): reads the mouse (the primary
  // finger, ui/widgets/touch_input.h) and scrolls the panel under a drag.
  void update(float slop_px);
  // The item just drawn takes drags itself (this frame's record; the next
  // frame's decision reads it).
  void takes_drags(unsigned id);
  // A drag is scrolling a panel now.
  bool scrolling() const { return mode_ == Mode::scrolling; }

 private:
  enum class Mode { none, pending, scrolling, control };
  Mode mode_ = Mode::none;
  ImVec2 start_{0, 0};
  unsigned window_ = 0;  // ImGui id of the window under the press
  ImVec2 start_scroll_{0, 0};
  std::set<unsigned> drag_items_, drag_items_last_;
};

// The frame's DragScroll (that of the last TouchTargets to begin a frame)
// records the last item as one that takes drags; nothing without one.
void last_item_takes_drags();

}  // namespace rockface::ui
