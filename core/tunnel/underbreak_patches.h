#pragma once
// The underbreak beyond tolerance as the geologist reads it: connected
// stretches of it on the developed view (profile_deviation.h), deepest first.
#include <vector>

#include "core/tunnel/profile_deviation.h"

namespace rockface::tunnel {

// Connected cells of underbreak beyond tolerance on the developed view
// (4-neighbours; the arc-length direction wraps round the profile).
// `position_of_cell` is each cell's place (row-major as d.view).
std::vector<UnderbreakPatch> underbreak_patches(
    const ProfileDeviation& d, double tolerance, double cell_s, double cell_c,
    const std::vector<ProfilePosition>& position_of_cell);

}  // namespace rockface::tunnel
