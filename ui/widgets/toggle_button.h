#pragma once
// A button that shows whether its choice is on (drawn pressed): which field
// a keypad types into, which mode a panel is in.
#include <string>

#include "ui/widgets/widgets.h"

namespace rockface::ui {

// width 0: the label's own width (as TouchTargets::button).
bool toggle_button(TouchTargets& targets, const std::string& label, bool on, bool enabled = true,
                   float width = 0);
// On the same line as the last item when it fits there (as button_in_row).
bool toggle_button_in_row(TouchTargets& targets, const std::string& label, bool on,
                          bool enabled = true);

}  // namespace rockface::ui
