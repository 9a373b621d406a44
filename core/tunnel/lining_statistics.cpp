#include "core/tunnel/lining_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockface::tunnel {

double median_of(std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = values.size();
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(values.begin(), mid, values.end());
  if (n % 2 == 1) return *mid;
  const double upper = *mid;
  const double lower = *std::max_element(values.begin(), mid);
  return 0.5 * (lower + upper);
}

LiningOffset lining_offset(std::span<const double> deviations) {
  LiningOffset out;
  std::vector<double> v(deviations.begin(), deviations.end());
  out.cells = v.size();
  if (v.empty()) return out;
  out.median_m = median_of(v);
  for (double& x : v) x = std::abs(x - out.median_m);
  // 1.4826 x MAD is sigma for normal errors; the median's standard error is
  // sqrt(pi / 2) = 1.2533 times the mean's.
  out.robust_sigma_m = 1.4826 * median_of(v);
  out.standard_error_m = 1.2533 * out.robust_sigma_m / std::sqrt(static_cast<double>(out.cells));
  return out;
}

std::vector<std::uint8_t> cells_off_the_lining(std::size_t rows, std::size_t cols,
                                               std::span<const double> deviation,
                                               std::span<const std::uint8_t> seen,
                                               const NeighbourSpacing& spacing, double slope,
                                               double noise_m, double max_island_m2) {
  const std::size_t cells = rows * cols;
  const double diagonal = std::hypot(spacing.along_chainage_m, spacing.along_outline_m);
  // The seen 8-neighbours of cell k (the outline wrapping) with their
  // distance on the developed view.
  auto for_each_neighbour = [&](std::size_t k, auto&& visit) {
    const std::size_t r = k / cols, c = k % cols;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        if (dr == 0 && dc == 0) continue;
        const long rr = static_cast<long>(r) + dr;
        if (rr < 0 || rr >= static_cast<long>(rows)) continue;
        const std::size_t cc =
            dc < 0 ? (c + cols - 1) % cols : (c + static_cast<std::size_t>(dc)) % cols;
        const std::size_t n = static_cast<std::size_t>(rr) * cols + cc;
        if (n == k || !seen[n]) continue;
        visit(n, dr != 0 && dc != 0 ? diagonal
                 : dr != 0          ? spacing.along_chainage_m
                                    : spacing.along_outline_m);
      }
  };
  auto agree = [&](std::size_t a, std::size_t b, double distance) {
    return std::abs(deviation[a] - deviation[b]) <= slope * distance + noise_m;
  };
  // Pieces of surface: seen cells joined through agreeing neighbours.
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> piece(cells, kNone), size;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < cells; ++start) {
    if (!seen[start] || piece[start] != kNone) continue;
    const std::size_t id = size.size();
    size.push_back(0);
    stack.assign(1, start);
    piece[start] = id;
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      ++size[id];
      for_each_neighbour(k, [&](std::size_t n, double distance) {
        if (piece[n] != kNone || !agree(k, n, distance)) return;
        piece[n] = id;
        stack.push_back(n);
      });
    }
  }
  // One cell that agrees with nothing; or a small piece that meets other
  // seen surface only across a jump (stray triangles behind a hole of the
  // wall): off the lining. A small piece alone among unseen cells is a
  // glimpse of the wall and stays.
  const double cell_m2 = spacing.along_chainage_m * spacing.along_outline_m;
  std::vector<std::uint8_t> beside_other(size.size(), 0);
  for (std::size_t k = 0; k < cells; ++k)
    if (seen[k])
      for_each_neighbour(k, [&](std::size_t n, double) {
        if (piece[n] != piece[k]) beside_other[piece[k]] = 1;
      });
  std::vector<std::uint8_t> off(cells, 0);
  for (std::size_t k = 0; k < cells; ++k) {
    if (!seen[k]) continue;
    const std::size_t id = piece[k];
    const bool island = beside_other[id] && static_cast<double>(size[id]) * cell_m2 < max_island_m2;
    off[k] = size[id] == 1 || island ? 1 : 0;
  }
  return off;
}

}  // namespace rockface::tunnel
