#pragma once
// The status line of each screen: the last message said on that screen
// (a task's outcome is said on the screen that started it, not on every
// screen), and the errors said there, which stay until the geologist taps
// them away — a failed save must not scroll away unread.
#include <cstddef>
#include <string>
#include <vector>

namespace rockface::ui {

class StatusLines {
 public:
  // `screen` is the index of a Screen (app_state.h).
  void say(std::size_t screen, std::string text);
  void error(std::size_t screen, std::string text);
  // Another visit was chosen: the messages were about the last one (the
  // errors stay until read).
  void clear_messages();
  // The errors were read (tapped).
  void dismiss(std::size_t screen);

  const std::string& message(std::size_t screen) const;
  const std::vector<std::string>& errors(std::size_t screen) const;
  // Errors first, then the message: what a script prints at its end.
  std::string line(std::size_t screen) const;

 private:
  struct Line {
    std::string message;
    std::vector<std::string> errors;
  };
  Line& at(std::size_t screen);
  const Line& at(std::size_t screen) const;
  std::vector<Line> lines_;
};

}  // namespace rockface::ui
