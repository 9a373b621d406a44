#pragma once
// The look and the touch targets of the tablet UI: a light, high-contrast
// theme readable in daylight, thumb-sized buttons, and a record of where
// every named button was drawn this frame, so that headless scripts (and
// tests) can tap a button by its label instead of by a pixel that moves when
// the layout changes.
#include <map>
#include <optional>
#include <string>

#include <imgui.h>

#include "ui/block_view.h"

namespace rockface::ui {

// Smallest edge of a touch target, in pixels at scale 1: 56 px on a 10"
// 1280x800 tablet (about 150 px per inch) is 9.5 mm, above the 9 mm
// usually asked for a thumb.
constexpr float kTouchTargetPx = 56;

// Sets ImGui's style and font for `scale` (1 = a 1280x800 tablet).
void apply_daylight_theme(float scale);

ImU32 verdict_colour(BlockVerdict verdict);
// Colour of traces marked on the model (magenta: no rock has it).
constexpr ImU32 kTraceColour = IM_COL32(255, 0, 200, 255);
constexpr ImU32 kPendingTraceColour = IM_COL32(0, 170, 255, 255);
constexpr ImU32 kTargetColour = IM_COL32(255, 230, 0, 255);

struct TargetRect {
  ImVec2 min, max;
  bool enabled = true;
  ImVec2 centre() const { return {(min.x + max.x) / 2, (min.y + max.y) / 2}; }
};

class TouchTargets {
 public:
  void begin_frame() { rects_.clear(); }
  // A thumb-sized button; width 0 fits the label. Records where it is.
  bool button(const std::string& label, float width = 0, bool enabled = true);
  // Records an area drawn by other means (the model view).
  void record(const std::string& label, ImVec2 min, ImVec2 max) { rects_[label] = {min, max}; }
  std::optional<TargetRect> find(const std::string& label) const;
  float scale() const { return scale_; }
  void set_scale(float s) { scale_ = s; }

 private:
  std::map<std::string, TargetRect> rects_;
  float scale_ = 1;
};

}  // namespace rockface::ui
