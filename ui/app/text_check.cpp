#include "ui/app/text_check.h"

#include <cctype>

#include "core/common/number_format.h"

namespace rockface::ui {

namespace {

bool lower(char c) {
  return c >= 'a' && c <= 'z';
}
bool digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

bool looks_like_key(std::string_view t) {
  // [a-z]+_[a-z_]+: at any position, by hand (std::regex is slow and this
  // runs on every string of every frame of the walk).
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!lower(t[i]) || (i > 0 && lower(t[i - 1]))) continue;
    std::size_t j = i;
    while (j < t.size() && lower(t[j])) ++j;
    if (j >= t.size() || t[j] != '_') continue;
    std::size_t k = j + 1;
    while (k < t.size() && (lower(t[k]) || t[k] == '_')) ++k;
    if (k > j + 1 && k < t.size() && t[k] == ':') return true;
  }
  return false;
}

bool looks_like_json(std::string_view t) {
  return t.find("{\"") != std::string_view::npos;
}

bool looks_like_field_path(std::string_view t) {
  auto word = [](char c) { return lower(c) || digit(c) || c == '_' || (c >= 'A' && c <= 'Z'); };
  // \w+\.\w+\[\d+\]: find "[digits]" preceded by word chars, a dot, word chars.
  for (std::size_t open = t.find('['); open != std::string_view::npos;
       open = t.find('[', open + 1)) {
    std::size_t close = open + 1;
    while (close < t.size() && digit(t[close])) ++close;
    if (close == open + 1 || close >= t.size() || t[close] != ']') continue;
    std::size_t i = open;
    while (i > 0 && word(t[i - 1])) --i;
    if (i == open || i == 0 || t[i - 1] != '.') continue;
    const std::size_t dot = i - 1;
    std::size_t j = dot;
    while (j > 0 && word(t[j - 1])) --j;
    if (j < dot) return true;
  }
  return false;
}

std::optional<std::string> overlong_number(std::string_view t, int max_digits) {
  for (std::size_t i = 0; i < t.size();) {
    if (!digit(t[i])) {
      ++i;
      continue;
    }
    // One number: digits, thousands commas between digit groups, one point.
    std::size_t j = i;
    int significant = 0;
    bool leading = true;
    while (j < t.size()) {
      const char c = t[j];
      if (digit(c)) {
        if (c != '0') leading = false;
        if (!leading) ++significant;
        ++j;
      } else if ((c == ',' || c == '.') && j + 1 < t.size() && digit(t[j + 1])) {
        ++j;
      } else {
        break;
      }
    }
    if (significant > max_digits) return std::string(t.substr(i, j - i));
    i = j;
  }
  return std::nullopt;
}

std::string text_problem(const DrawnText& d, float slack_px) {
  std::string why;
  auto add = [&](const std::string& s) { why += (why.empty() ? "" : "; ") + s; };
  if (d.width > d.available + slack_px) {
    add(format_fixed(d.width, 0, " px") + " wide in " + format_fixed(d.available, 0, " px"));
  }
  if (looks_like_key(d.text)) add("looks like a report key");
  if (looks_like_json(d.text)) add("looks like JSON");
  if (looks_like_field_path(d.text)) add("names a library's field path, not in words");
  if (const auto n = overlong_number(d.text)) add("the number " + *n + " has too many digits");
  return why.empty() ? why : "\"" + d.text + "\" in " + d.panel + ": " + why;
}

}  // namespace rockface::ui
