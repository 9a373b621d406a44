#pragma once
// A counted break's flanks followed down to the design (issue 38). The
// noise threshold keeps a break's shallow edge out of the count: on the test
// headings' smooth breaks (sin^2 edges, 0.1-0.35 m deep) the cells within
// one to two sigma of the design held 8-10 % of each break's volume, and
// every break read that much short. From each counted cell the count goes
// on into a neighbour of the same sign whose deviation is no deeper: a
// break's flank descends to the design, so the whole of it is taken, while
// the noise beside it, of either sign and rising as often as falling, adds
// a cell or two at most. Nothing is started from a cell that is not already
// counted, so noise away from a break still counts for nothing.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rockface::tunnel {

// sign: per cell (row-major, rows x cols; rows are sections, columns rays
// round the outline, which wraps) +1 overbreak, -1 underbreak, 0 none: the
// breaks that count (break_significance.h). deviation: per cell, m (the
// lining's offset removed), read where valued. Returns the signs with each
// break's flanks added.
std::vector<std::int8_t> follow_break_flanks(std::size_t rows, std::size_t cols,
                                             const std::vector<std::int8_t>& sign,
                                             const std::vector<double>& deviation,
                                             const std::vector<std::uint8_t>& valued);

}  // namespace rockface::tunnel
