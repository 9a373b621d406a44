#include "ui/widgets/widgets_scroll.h"

#include <cmath>

#include <imgui_internal.h>

namespace rockface::ui {

namespace {

// The id the drag holds while it scrolls (or while a press on a scroll bar
// waits to become a drag): no item has it, so none is pressed meanwhile.
ImGuiID drag_id() {
  static const ImGuiID id = ImHashStr("rockface drag scroll");
  return id;
}

// The window itself, then the windows it is a child of (a table's scrolling
// region, its side panel, the screen); a popup (an open choice's list) or
// the top window ends the chain.
ImGuiWindow* next_out(ImGuiWindow* w) {
  return (w->Flags & ImGuiWindowFlags_ChildWindow) ? w->ParentWindow : nullptr;
}

bool scrolls(const ImGuiWindow* w) {
  return !(w->Flags & ImGuiWindowFlags_NoInputs) && (w->ScrollMax.y > 0 || w->ScrollMax.x > 0);
}

// The panel a drag by `delta` from inside `hovered` scrolls: the innermost
// that can still move that way (a table at its end hands the drag on to its
// side panel, as nested lists do on a tablet), else the innermost that
// scrolls at all (the drag stays a scroll, at its end, and presses nothing).
ImGuiWindow* panel_to_scroll(ImGuiWindow* hovered, ImVec2 delta) {
  const bool vertical = std::fabs(delta.y) >= std::fabs(delta.x);
  ImGuiWindow* any = nullptr;
  for (ImGuiWindow* w = hovered; w; w = next_out(w)) {
    if (!scrolls(w)) continue;
    if (!any) any = w;
    // A finger dragged down pulls the content down: the scroll goes back.
    const float d = vertical ? delta.y : delta.x;
    const float at = vertical ? w->Scroll.y : w->Scroll.x;
    const float most = vertical ? w->ScrollMax.y : w->ScrollMax.x;
    if ((d > 0 && at > 0) || (d < 0 && at < most)) return w;
  }
  return any;
}

bool on_scroll_bar(ImGuiWindow* hovered, ImVec2 at) {
  for (ImGuiWindow* w = hovered; w; w = next_out(w)) {
    if (w->ScrollbarY && ImGui::GetWindowScrollbarRect(w, ImGuiAxis_Y).Contains(at)) return true;
    if (w->ScrollbarX && ImGui::GetWindowScrollbarRect(w, ImGuiAxis_X).Contains(at)) return true;
  }
  return false;
}

}  // namespace

void DragScroll::takes_drags(unsigned id) {
  drag_items_.insert(id);
}

void DragScroll::update(float slop_px) {
  drag_items_last_.swap(drag_items_);
  drag_items_.clear();
  ImGuiContext* g = ImGui::GetCurrentContext();
  if (!g || !g->WithinFrameScope) return;
  const ImGuiIO& io = g->IO;
  const ImGuiID id = drag_id();
  if (!io.MouseDown[0]) {
    // The finger is up: whatever it was doing ends (a scroll leaves no press).
    if (g->ActiveId == id) ImGui::ClearActiveID();
    mode_ = Mode::none;
    return;
  }
  if (io.MouseClicked[0]) {
    mode_ = Mode::pending;
    start_ = io.MouseClickedPos[0];
    window_ = g->HoveredWindow ? g->HoveredWindow->ID : 0;
    // The scroll bar only shows where the content is: a press on it is the
    // start of a drag of its panel, never a jump of the content.
    if (g->HoveredWindow && on_scroll_bar(g->HoveredWindow, start_))
      ImGui::SetActiveID(id, g->HoveredWindow);
  }
  ImGuiWindow* hovered = window_ ? ImGui::FindWindowByID(window_) : nullptr;
  const ImVec2 delta(io.MousePos.x - start_.x, io.MousePos.y - start_.y);
  if (mode_ == Mode::pending && std::hypot(delta.x, delta.y) > slop_px) {
    ImGuiWindow* panel = hovered ? panel_to_scroll(hovered, delta) : nullptr;
    if ((g->ActiveId && drag_items_last_.count(g->ActiveId)) || !panel) {
      // A slider, the 3D image or a handle keeps its drag; with nothing to
      // scroll the press stays ImGui's (pressed only if released on it).
      mode_ = Mode::control;
    } else {
      mode_ = Mode::scrolling;
      window_ = panel->ID;
      hovered = panel;
      start_scroll_ = panel->Scroll;
      // The control the finger went down on loses its press.
      ImGui::SetActiveID(id, panel);
    }
  }
  if (g->ActiveId == id) ImGui::KeepAliveID(id);
  if (mode_ != Mode::scrolling || !hovered) return;
  // The content follows the finger (clamped to the panel's range when the
  // panel is begun this frame).
  if (hovered->ScrollMax.y > 0) ImGui::SetScrollY(hovered, start_scroll_.y - delta.y);
  if (hovered->ScrollMax.x > 0) ImGui::SetScrollX(hovered, start_scroll_.x - delta.x);
}

}  // namespace rockface::ui
