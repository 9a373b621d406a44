#pragma once
// A button that shows whether its choice is on (drawn pressed): which field
// a keypad types into, which mode a panel is in.
#include <string>

#include "ui/widgets/widgets.h"

namespace rockface::ui {

bool toggle_button(TouchTargets& targets, const std::string& label, bool on, bool enabled = true);

}  // namespace rockface::ui
