#pragma once
// A round's over- and underbreak per cross-section as CSV (spreadsheets, the
// contractor's measurement sheet): one row per section, header
//   chainage,overbreak_m2,underbreak_m2,max_overbreak_m,max_underbreak_m,seen_fraction,roof_seen,walls_seen,floor_seen
// Areas of the seen part of the outline (m²), depths normal to the design
// line (m), fractions of the outline's length in [0, 1]. A section that saw
// nothing has its figures empty, not 0: they are unknown.
#include <ostream>

#include "core/tunnel/profile_deviation.h"

namespace rockface::storage {

std::size_t write_deviation_csv(std::ostream& out, const tunnel::ProfileDeviation& deviation);

}  // namespace rockface::storage
