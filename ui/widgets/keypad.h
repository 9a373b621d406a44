#pragma once
// A keypad of thumb-sized keys (9 mm): the tablet has no keyboard, and a
// gloved hand does not hit a phone keyboard's keys. Digits, the point and
// Back in three rows of four; what is typed is the caller's (TypedNumber).
#include <cstddef>
#include <optional>
#include <string>

#include "ui/widgets/widgets.h"

namespace rockface::ui {

// The key tapped this frame: '0'..'9', '.', or '\b' for Back.
std::optional<char> draw_keypad(TouchTargets& targets);

// A number typed on the keypad as a compass is read: up to `max_chars`
// characters, one decimal; the first key after clear() replaces the value.
class TypedNumber {
 public:
  explicit TypedNumber(std::size_t max_chars = 5) : max_chars_(max_chars) {}
  // False when the key was not taken (a second point, a second decimal,
  // too many digits, anything else).
  bool key(char c);
  void clear() { typed_.clear(); }
  const std::string& text() const { return typed_; }
  double value() const;  // 0 when nothing is typed

 private:
  std::size_t max_chars_;
  std::string typed_;
};

}  // namespace rockface::ui
