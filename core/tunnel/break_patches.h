#pragma once
// The robust patch rule of the developed view (issue 38): a cell counts as
// over- or underbreak only inside a patch of counted cells of its sign at
// least a few sections long and a few rays wide. The reconstruction's
// errors that pass the noise threshold lie in narrow bands (a grazing
// wall's streaks, a terrace edge, the crease by the face: one section or a
// few rays across), while a blast's break that matters for the round's
// volume spans metres. The counted cells are opened (morphological opening:
// kept where a whole rectangle of them of one sign covers the cell, cells
// without a value inside the rectangle not held against it), so a band
// narrower than the rectangle counts for nothing and a break keeps its
// area, flanks included, wherever the rectangle fits. The rectangle must lie
// inside the round: a band at the round's ends shorter than it counts for
// nothing either (the crease where the face meets the lining).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rockface::tunnel {

struct PatchSize {
  std::size_t half_rows = 1;  // the rectangle is 2 half_rows + 1 sections long
  std::size_t half_cols = 2;  // and 2 half_cols + 1 rays wide
};

// sign: per cell (row-major, rows x cols; the rows are sections, the
// columns rays round the outline, which wraps) +1 counted as overbreak,
// -1 as underbreak, 0 not counted. valued: per cell, whether it has a
// deviation (measured or interpolated). Returns the signs kept.
std::vector<std::int8_t> open_break_patches(std::size_t rows, std::size_t cols,
                                            const std::vector<std::int8_t>& sign,
                                            const std::vector<std::uint8_t>& valued,
                                            const PatchSize& size);

// The rectangle for cells of cell_c (m along the chainage) by cell_s (m
// along the outline): along each, the largest odd count of cells within
// min_chainage_m and min_outline_m (one cell at least).
PatchSize patch_size_for(double min_chainage_m, double min_outline_m, double cell_c, double cell_s);

}  // namespace rockface::tunnel
