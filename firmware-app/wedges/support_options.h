#pragma once
// The support typed for `rockface wedges` on a project and on the tablet's
// Wedges form: "LENGTH,SPACING,CAPACITY[,BOND]" of pattern bolts and
// "THICKNESS,SHEAR_STRENGTH" of shotcrete, in SI units, each value within
// the range the scene's wedges section takes (core/tunnel/support_ranges.h,
// storage/scene/scene_wedges_json.cpp). Bad text throws InputError naming
// `where` (the option) and the value.
#include <string>

#include "core/tunnel/wedge_analysis.h"

namespace rockface::app {

tunnel::PatternBolts parse_pattern_bolts(const std::string& text, const std::string& where);
tunnel::Shotcrete parse_shotcrete(const std::string& text, const std::string& where);

}  // namespace rockface::app
