#include "core/common/preset.h"

#include "core/common/error.h"

namespace rockface {

namespace {

constexpr Preset kPresets[] = {Preset::fast, Preset::standard, Preset::precise};

}  // namespace

Preset parse_preset(std::string_view name, const std::string& where) {
  for (const Preset p : kPresets)
    if (name == preset_name(p)) return p;
  if (name.empty()) throw InputError(where, "no preset given (fast | standard | precise)");
  throw InputError(where, "unknown preset '" + std::string(name) + "' (fast | standard | precise)");
}

std::string_view preset_name(Preset preset) {
  switch (preset) {
    case Preset::fast:
      return "fast";
    case Preset::standard:
      return "standard";
    case Preset::precise:
      return "precise";
  }
  return "standard";  // not reached: every enumerator is handled above
}

}  // namespace rockface
