#pragma once
// The named presets that trade accuracy for time (DESIGN.md "Accuracy costs
// time"). A preset name is decoded here and nowhere else: each boundary (the
// scene file, the command line, a stored record) calls parse_preset once, and
// each module maps the value to its own options (reconstruction knobs,
// remote-axis starts, equilibrium-path contacts and step).
#include <string>
#include <string_view>

namespace rockface {

enum class Preset { fast, standard, precise };

// The preset called `name`. Throws InputError naming `where` (a field such as
// "analysis.preset", or "--preset") and listing the valid names for anything
// else, the empty name included: an unknown name is refused, never defaulted.
Preset parse_preset(std::string_view name, const std::string& where);

// "fast", "standard" or "precise": what files, records and reports hold.
std::string_view preset_name(Preset preset);

}  // namespace rockface
