#pragma once
// The developed view's grid of cells (profile_deviation.h's DevelopedView):
// row-major, rows x cols; the rows are cross-sections along the chainage,
// cut at the round's ends, the columns rays round the outline, which wraps.
// The counting rules that walk it (break_patches.h, break_significance.h,
// break_flanks.h, underbreak_patches.h) share these two steps.
#include <algorithm>
#include <array>
#include <cstddef>

namespace rockface::tunnel {

// Cell k's four neighbours: the sections before and after it (k itself at
// the round's ends) and the rays on either side of it (wrapping).
inline std::array<std::size_t, 4> developed_neighbours(std::size_t k, std::size_t rows,
                                                       std::size_t cols) {
  const std::size_t r = k / cols, c = k % cols;
  return {r > 0 ? k - cols : k, r + 1 < rows ? k + cols : k, r * cols + (c + cols - 1) % cols,
          r * cols + (c + 1) % cols};
}

// Calls f(q) for every cell of the rectangle of half_rows sections and
// half_cols rays on each side of (r, c): rows cut at the round's ends,
// columns wrapping round the outline (each once, however wide).
template <typename F>
void for_developed_rectangle(std::size_t r, std::size_t c, std::size_t rows, std::size_t cols,
                             std::size_t half_rows, std::size_t half_cols, F&& f) {
  const std::size_t r0 = r >= half_rows ? r - half_rows : 0;
  const std::size_t r1 = std::min(rows - 1, r + half_rows);
  const std::size_t wide = std::min(cols, 2 * half_cols + 1);
  for (std::size_t rr = r0; rr <= r1; ++rr)
    for (std::size_t i = 0; i < wide; ++i) f(rr * cols + (c + cols - half_cols % cols + i) % cols);
}

}  // namespace rockface::tunnel
