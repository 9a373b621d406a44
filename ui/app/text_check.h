#pragma once
// What a label on the tablet must not look like: a report key
// ("sigma_z: 0.0021"), JSON ('{"image_scale":1}'), a number with more
// digits than any field figure has (more than 6 significant digits, e.g.
// 0.98327413), or text wider than the space it was drawn in. The screen
// walk of tests/ui checks every string drawn (ui/widgets/widgets.h records them).
#include <optional>
#include <string>
#include <string_view>

namespace rockface::ui {

// A lower-case word with an underscore, followed by a colon (regex
// `[a-z]+_[a-z_]+:`).
bool looks_like_key(std::string_view text);
// An opening brace followed by a double quote.
bool looks_like_json(std::string_view text);
// A library's field path with an index, as its error messages name what
// they refuse ("trace.pixels[784]", regex `\w+\.\w+\[\d+\]`): the message
// was not put in words for the screen.
bool looks_like_field_path(std::string_view text);
// The first number in `text` printed with more than `max_digits`
// significant digits (leading zeros do not count; "1,234,567" is one
// number), if any.
std::optional<std::string> overlong_number(std::string_view text, int max_digits = 6);

struct DrawnText {
  std::string text;
  float width = 0;      // as drawn, px
  float available = 0;  // from where it started to the right edge of its panel, px
  std::string panel;    // the ImGui window it was drawn in (for the message)
};

// What is wrong with a drawn string, in words; empty when nothing is.
// `slack_px` is the rounding of ImGui's layout (a fraction of a pixel).
std::string text_problem(const DrawnText& drawn, float slack_px = 1.0f);

}  // namespace rockface::ui
