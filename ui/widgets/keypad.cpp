#include "ui/widgets/keypad.h"

#include <cstdlib>

#include "ui/widgets/widgets_controls.h"

namespace rockface::ui {

std::optional<char> draw_keypad(TouchTargets& targets) {
  std::optional<char> pressed;
  const char* rows[3][4] = {{"7", "8", "9", "Back"}, {"4", "5", "6", "."}, {"1", "2", "3", "0"}};
  for (const auto& row : rows)
    for (int k = 0; k < 4; ++k) {
      const bool back = row[k][1] != 0;
      const float width = back ? 0.0f : targets.target_px();
      if (k > 0) same_line_if_fits(back ? button_width(row[k], width) : width);
      if (targets.button(row[k], width)) pressed = back ? '\b' : row[k][0];
    }
  return pressed;
}

bool TypedNumber::key(char c) {
  if (c == '\b') {
    if (typed_.empty()) return false;
    typed_.pop_back();
    return true;
  }
  if (c == '.') {
    if (typed_.find('.') != std::string::npos || typed_.size() >= max_chars_) return false;
    typed_ += typed_.empty() ? "0." : ".";
    return true;
  }
  if (c < '0' || c > '9') return false;
  // One decimal, as a compass is read (to 0.5-1 degree).
  const auto point = typed_.find('.');
  if (typed_.size() >= max_chars_ || (point != std::string::npos && typed_.size() > point + 1))
    return false;
  typed_ += c;
  return true;
}

double TypedNumber::value() const {
  return typed_.empty() ? 0.0 : std::strtod(typed_.c_str(), nullptr);
}

}  // namespace rockface::ui
