#pragma once
// What the geologist is told of a round's over- and underbreak: the status
// and the message of profile_deviation.h, with what the figures leave out
// and why (issue 38).
#include <cstddef>
#include <string>

#include "core/tunnel/lining_precision.h"
#include "core/tunnel/profile_deviation.h"

namespace rockface::tunnel {

// What the geologist is told: the status and its message, with what the
// figures leave out and why.
// `seen` and `excluded`: the cells measured and stopped by what is not
// rock; `clipped` what the range's cut to the alignment says; `per_cell`
// the cells' own precision when each had one (lining_precision.h).
void tell_the_geologist(ProfileDeviation& out, const DeviationOptions& options, std::size_t seen,
                        std::size_t excluded, const std::string& clipped,
                        const CellPrecisionFigures* per_cell);

}  // namespace rockface::tunnel
