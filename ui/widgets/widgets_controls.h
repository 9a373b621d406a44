#pragma once
// The controls of the tablet besides buttons — sliders, check boxes,
// choices (combos), collapsing sections and typed fields — each a thumb
// target recorded with the frame's touch targets, and each text it draws
// (a slider's value, a box's label, the items of a choice, a typed value)
// recorded with the text the walk checks (ui/widgets/widgets_text.h). Screens use
// these, never ImGui's own.
#include <optional>
#include <string>
#include <vector>

#include "ui/widgets/widgets.h"

namespace rockface::ui {

// A slider `width` px wide (-1: the rest of the line). `format` is printf's, for the
// value as drawn in the slider ("%.0f m"). Its frame is a target high and
// its grab a target wide and high: a gloved thumb drags it. Recorded as
// touch target `name`. True when the value changed.
bool slider(TouchTargets& targets, const std::string& name, float* value, float lo, float hi,
            const char* format, float width = -1);

// A box and its label (empty: none shown); the box is a target square.
bool checkbox(TouchTargets& targets, const std::string& name, const std::string& label,
              bool* checked);

// A choice among `items` filling the rest of the line, showing `shown`;
// the list's items are target-high rows. The index tapped, if any.
std::optional<std::size_t> choice(TouchTargets& targets, const std::string& name,
                                  const std::string& shown, const std::vector<std::string>& items,
                                  std::optional<std::size_t> current);

// A section that opens and closes (its header a target high).
bool collapsing_section(TouchTargets& targets, const std::string& title, bool open_at_first);

// Typed fields: a line of text, a number (`format` printf's, as drawn)
// `width` px wide; with `step` > 0, "-" and "+" buttons (targets square)
// step it by `step`.
bool text_field(TouchTargets& targets, const std::string& name, std::string* text);
bool number_field(TouchTargets& targets, const std::string& name, double* value, const char* format,
                  float width, double step = 0);

// The grab of a slider drawn over [min, max] at `fraction` of its range,
// as ImGui 1.86 lays it out (SliderBehaviorT: the grab is GrabMinSize
// wide, inset 2 px from the frame): what the walk holds to 9 mm.
struct GrabRect {
  ImVec2 min, max;
};
GrabRect slider_grab(ImVec2 frame_min, ImVec2 frame_max, float fraction, float grab_width);

}  // namespace rockface::ui
