#include "core/tunnel/break_patches.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/common/error.h"
#include "core/tunnel/developed_cells.h"

namespace rockface::tunnel {

namespace {

// The patch rule's rectangle about (r, c) (developed_cells.h).
template <typename F>
void for_rectangle(std::size_t r, std::size_t c, std::size_t rows, std::size_t cols,
                   const PatchSize& size, F&& f) {
  for_developed_rectangle(r, c, rows, cols, size.half_rows, size.half_cols, std::forward<F>(f));
}

}  // namespace

std::vector<std::int8_t> open_break_patches(std::size_t rows, std::size_t cols,
                                            const std::vector<std::int8_t>& sign,
                                            const std::vector<std::uint8_t>& valued,
                                            const PatchSize& size) {
  if (sign.size() != rows * cols || valued.size() != rows * cols)
    throw InputError("break patches",
                     "one sign and one valued flag per cell (" + std::to_string(rows * cols) + ")");
  // Erosion: where the whole rectangle is of the cell's sign and lies inside
  // the round. A rectangle cut at the round's ends would let a band of one
  // or two sections there count: the crease where the face meets the
  // lining, which the dense matching's window smears over the last half
  // metre of a round (issue 38: 0.01 m3 of underbreak on the D heading's
  // last two sections). A break longer than the rectangle keeps its cells
  // up to the ends (the dilation below is cut there). A round shorter than
  // the rectangle takes as many sections as it has.
  PatchSize fits = size;
  fits.half_rows = std::min(size.half_rows, rows > 0 ? (rows - 1) / 2 : 0);
  std::vector<std::uint8_t> core(rows * cols, 0);
  for (std::size_t r = fits.half_rows; r + fits.half_rows < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) {
      const std::size_t k = r * cols + c;
      if (sign[k] == 0) continue;
      bool whole = true;
      for_rectangle(r, c, rows, cols, fits, [&](std::size_t q) {
        if (valued[q] && sign[q] != sign[k]) whole = false;
      });
      core[k] = whole ? 1 : 0;
    }
  // Dilation within the counted cells of the same sign.
  std::vector<std::int8_t> kept(rows * cols, 0);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) {
      const std::size_t k = r * cols + c;
      if (!core[k]) continue;
      for_rectangle(r, c, rows, cols, fits, [&](std::size_t q) {
        if (sign[q] == sign[k]) kept[q] = sign[k];
      });
    }
  return kept;
}

PatchSize patch_size_for(double min_chainage_m, double min_outline_m, double cell_c,
                         double cell_s) {
  auto half = [](double min_m, double cell_m) {
    if (!(cell_m > 0) || !(min_m > 0)) return std::size_t{0};
    // The largest odd count of cells within min_m (a hair over, for the
    // rounding of a range cut into equal sections).
    const double cells = min_m / cell_m + 1e-9;
    return static_cast<std::size_t>(std::max(0.0, std::floor(cells / 2)));
  };
  return {half(min_chainage_m, cell_c), half(min_outline_m, cell_s)};
}

}  // namespace rockface::tunnel
