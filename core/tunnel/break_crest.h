#pragma once
// The round's largest over- and underbreak on the developed view (issue
// 38): a cell's depth as a candidate for the largest, but no deeper than
// the second deepest of its four neighbours that carry a value (the
// outline wrapping), so that one cell, or two side by side, that a stray
// triangle or a hole's edge put far off their neighbours (0.40 m read where
// the scene has 0.03 m) cannot make the round's largest. On a break's crest
// the neighbours along the outline (5 cm away) lie within a millimetre of
// it, so the largest stays the crest's depth.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace rockface::tunnel {

// deviation: per cell (row-major, rows x cols; the rows are sections, the
// columns rays round the outline, which wraps), the normal deviation with
// the lining's offset taken out, + outward. valued: whether a cell has a
// deviation (measured or interpolated). candidate: the cells that may be
// the largest (counted and measured). Returns, per candidate, its capped
// deviation with its own sign (an overbreak cell is capped toward zero by
// its neighbours' outward depths, an underbreak cell by their inward ones);
// nothing for the other cells and for a candidate with fewer than two
// valued neighbours.
std::vector<std::optional<double>> break_crest_depths(std::size_t rows, std::size_t cols,
                                                      const std::vector<double>& deviation,
                                                      const std::vector<std::uint8_t>& valued,
                                                      const std::vector<std::uint8_t>& candidate);

}  // namespace rockface::tunnel
