#include "ui/app/status_lines.h"

namespace rockface::ui {

StatusLines::Line& StatusLines::at(std::size_t screen) {
  if (screen >= lines_.size()) lines_.resize(screen + 1);
  return lines_[screen];
}

const StatusLines::Line& StatusLines::at(std::size_t screen) const {
  static const Line none;
  return screen < lines_.size() ? lines_[screen] : none;
}

void StatusLines::say(std::size_t screen, std::string text) {
  at(screen).message = std::move(text);
}

void StatusLines::error(std::size_t screen, std::string text) {
  auto& errors = at(screen).errors;
  // The same error again (a retried sync) is one error to read.
  for (const auto& e : errors)
    if (e == text) return;
  errors.push_back(std::move(text));
}

void StatusLines::clear_messages() {
  for (auto& line : lines_) line.message.clear();
}

void StatusLines::dismiss(std::size_t screen) {
  at(screen).errors.clear();
}

const std::string& StatusLines::message(std::size_t screen) const {
  return at(screen).message;
}

const std::vector<std::string>& StatusLines::errors(std::size_t screen) const {
  return at(screen).errors;
}

std::string StatusLines::line(std::size_t screen) const {
  std::string out;
  for (const auto& e : errors(screen)) out += (out.empty() ? "" : "; ") + e;
  if (!message(screen).empty()) out += (out.empty() ? "" : "; ") + message(screen);
  return out;
}

}  // namespace rockface::ui
