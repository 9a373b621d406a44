#include "firmware-app/support/support_change_text.h"

#include "core/common/error.h"

namespace rockface::app {

namespace {

std::string trim_change_field(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t");
  return s.substr(a, b - a + 1);
}

constexpr const char* kChangeForm = "\"WHAT: FROM -> TO: REASON\"";

}  // namespace

analysis::SupportChange parse_support_change(const std::string& text, const std::string& where) {
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError(where, "\"" + text + "\" names no change: write " + kChangeForm);
  // "->", or the arrow a keyboard with symbols gives.
  std::size_t arrow = text.find("->", colon + 1), arrow_len = 2;
  if (arrow == std::string::npos) {
    arrow = text.find("\u2192", colon + 1);
    arrow_len = std::string("\u2192").size();
  }
  if (arrow == std::string::npos)
    throw InputError(where, "\"" + text + "\" gives no FROM -> TO: write " + kChangeForm);
  const auto reason = text.find(':', arrow + arrow_len);
  if (reason == std::string::npos)
    throw InputError(where, "\"" + text + "\" gives no reason: write " + kChangeForm);
  analysis::SupportChange c;
  c.what = trim_change_field(text.substr(0, colon));
  c.from = trim_change_field(text.substr(colon + 1, arrow - colon - 1));
  c.to = trim_change_field(text.substr(arrow + arrow_len, reason - arrow - arrow_len));
  c.reason = trim_change_field(text.substr(reason + 1));
  require_complete(c, where);
  return c;
}

void require_complete(const analysis::SupportChange& c, const std::string& where) {
  const std::string name = c.what.empty() ? "a change" : "the change of " + c.what;
  if (c.what.empty()) throw InputError(where, "a change names what was changed");
  if (c.from.empty()) throw InputError(where, name + " says what the class gives (FROM)");
  if (c.to.empty()) throw InputError(where, name + " says what it was changed to (TO)");
  if (c.reason.empty()) throw InputError(where, name + " says why (REASON)");
}

std::string support_change_words(const analysis::SupportChange& c) {
  return c.what + " " + c.from + " -> " + c.to + " (" + c.reason + ")";
}

}  // namespace rockface::app
