#pragma once
// The touch targets of the tablet UI: thumb-sized buttons (at least 9 mm at
// the tablet's DPI), rows of buttons that wrap, and a record of where
// every named button was drawn this frame, so that headless scripts (and
// tests) can tap a button by its label instead of by a pixel that moves when
// the layout changes.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "ui/blocks/block_view.h"
#include "ui/widgets/theme.h"
#include "ui/widgets/widgets_scroll.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

// Smallest edge of a touch target, in pixels at scale 1: 56 px on a 10"
// 1280x800 tablet (about 150 px per inch) is 9.5 mm, above the 9 mm
// usually asked for a thumb.
constexpr float kTouchTargetPx = 56;
// The pixel density scale 1 stands for (a 10" 1280 x 800 tablet).
constexpr float kScaleOneDpi = 150;
// The smallest touch target a gloved thumb hits, mm.
constexpr float kTouchTargetMm = 9;
// Pixels of kTouchTargetMm at `dpi`.
inline float touch_target_px_at(float dpi) {
  return kTouchTargetMm / 25.4f * dpi;
}

ImU32 verdict_colour(analysis::BlockVerdict verdict);
// The verdict's colour for text on the current theme's background (the
// yellow of "holds" is unreadable on daylight white: darker there).
ImU32 verdict_text_colour(analysis::BlockVerdict verdict);
// Colour of traces marked on the model (magenta: no rock has it).
constexpr ImU32 kTraceColour = IM_COL32(255, 0, 200, 255);
constexpr ImU32 kPendingTraceColour = IM_COL32(0, 170, 255, 255);
constexpr ImU32 kTargetColour = IM_COL32(255, 230, 0, 255);

// A panel a target is drawn in, as a finger sees it: `inner` is the panel's
// content area on the screen (where its content shows when the panel itself
// is in view), `clip` the part of it on the screen now (inside every panel
// it lies in). Innermost first; a drag inside `clip` scrolls it
// (ui/widgets/widgets_scroll.h).
struct ScrollView {
  ImVec2 inner_min, inner_max;
  ImVec2 clip_min, clip_max;
  bool scrolls = false;  // its content is taller or wider than the panel
  bool clip_empty() const { return clip_max.x <= clip_min.x || clip_max.y <= clip_min.y; }
};

struct TargetRect {
  ImVec2 min, max;
  bool enabled = true;
  bool button = false;  // drawn by button(): a touch target of its own
  bool visible = true;  // not scrolled out of its panel's view
  // A finger taps it (a button, a row, a slider, a marker on the model):
  // the walk holds it to 9 mm. An area only shown (a notice, a cell) is not.
  bool touch = true;
  // The part inside its panel's view (the whole when drawn outside a
  // panel): where a finger can tap it.
  ImVec2 shown_min, shown_max;
  // It takes drags itself (a slider, the 3D image's handles): a drag begun
  // on it does not scroll its panel.
  bool drags = false;
  // The panels it lies in, innermost first (empty outside a panel).
  std::vector<ScrollView> views;
  ImVec2 centre() const { return {(min.x + max.x) / 2, (min.y + max.y) / 2}; }
  ImVec2 shown_centre() const {
    return {(shown_min.x + shown_max.x) / 2, (shown_min.y + shown_max.y) / 2};
  }
};

class TouchTargets {
 public:
  // Clears the record and makes these the frame's targets for
  // record_touch_target() (widgets drawn without them, e.g. a popup's Close);
  // in a frame (after ImGui::NewFrame, before the first window), a finger's
  // drag scrolls the panel under it (ui/widgets/widgets_scroll.h).
  void begin_frame();
  // A thumb-sized button; width 0 fits the label. Records where it is.
  bool button(const std::string& label, float width = 0, bool enabled = true);
  // The same, on the line of the previous item when it fits there, else on
  // the next line: rows of buttons that wrap in portrait.
  bool button_in_row(const std::string& label, bool enabled = true);
  // A button whose action loses work: the first tap asks `question` with
  // "Yes, <verb>" and "Keep" (both touch targets); true once confirmed.
  bool confirmed_button(const std::string& label, const std::string& question, bool enabled = true);
  // Edge of a touch target in pixels: the larger of kTouchTargetPx at the
  // UI scale and 9 mm at the tablet's DPI.
  float target_px() const;
  // Records a touch target drawn by other means (a table row, a slider, a
  // block's marker on the model): the one function every target goes
  // through, so that the walk holds each to 9 mm.
  void record(const std::string& label, ImVec2 min, ImVec2 max, bool enabled = true);
  // Records an area that is shown, not tapped (a notice, a table cell).
  void record_area(const std::string& label, ImVec2 min, ImVec2 max);
  // Records a target that takes drags itself (a slider, a handle dragged
  // on the model, a step button that repeats while held): a drag begun on
  // ImGui item `id` is left to it and scrolls nothing.
  void record_dragged(const std::string& label, ImVec2 min, ImVec2 max, unsigned id);
  std::optional<TargetRect> find(const std::string& label) const;
  float scale() const { return scale_; }
  void set_scale(float s) { scale_ = s; }
  float dpi() const { return dpi_; }
  void set_dpi(float dpi) { dpi_ = dpi; }
  // Edge of the slop between a tap and a drag, pixels at the DPI.
  float drag_slop_px() const { return kDragSlopMm / 25.4f * dpi_; }
  DragScroll& drag_scroll() { return drag_scroll_; }
  // Every target drawn this frame (the walk checks their size).
  const std::map<std::string, TargetRect>& all() const { return rects_; }

 private:
  std::map<std::string, TargetRect> rects_;
  float scale_ = 1;
  float dpi_ = kScaleOneDpi;
  DragScroll drag_scroll_;
};

// Records a touch target into the frame's TouchTargets (the last to begin a
// frame); nothing when none did (a widget drawn outside the tablet app).
void record_touch_target(const std::string& label, ImVec2 min, ImVec2 max);

// The edge of a touch target this frame: the frame's TouchTargets'
// target_px(), or ImGui's frame height (the theme makes it a target) when
// none began a frame.
float touch_target_px();

// The touch targets of `targets` a finger can reach (not scrolled out of
// view) that are smaller than 9 mm at its DPI, each in words with its size;
// `slack_px` is ImGui's rounding of item rectangles.
std::vector<std::string> small_touch_targets(const TouchTargets& targets, float slack_px = 0.5f);

// The width a button of `label` takes (its text and padding, at least a
// touch target).
float button_width(const std::string& label, float target_px);
// The main area (the 3D image) and a side panel of `side_px`: beside it in
// landscape, below it in portrait (the panel then gets `below` of the height).
struct SplitLayout {
  ImVec2 main;
  bool stacked = false;  // portrait: the panel is below, not beside
};
SplitLayout split_for_side_panel(float side_px, float below = 0.45f);
// Starts the side panel after the main area (SameLine in landscape).
void begin_side_panel(const char* id, const SplitLayout& layout, bool border = false);

// SameLine() when an item `width` px wide fits after the previous item.
void same_line_if_fits(float width);

}  // namespace rockface::ui
