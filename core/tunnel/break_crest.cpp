#include "core/tunnel/break_crest.h"

#include <algorithm>
#include <limits>

namespace rockface::tunnel {

std::vector<std::optional<double>> break_crest_depths(std::size_t rows, std::size_t cols,
                                                      const std::vector<double>& deviation,
                                                      const std::vector<std::uint8_t>& valued,
                                                      const std::vector<std::uint8_t>& candidate) {
  std::vector<std::optional<double>> out(rows * cols);
  for (std::size_t k = 0; k < rows * cols; ++k) {
    if (!candidate[k]) continue;
    const std::size_t r = k / cols, c = k % cols;
    const double sign = deviation[k] > 0 ? 1.0 : -1.0;  // depths counted positive either way
    double first = -std::numeric_limits<double>::infinity(), second = first;
    std::size_t n = 0;
    auto take = [&](std::size_t q) {
      if (!valued[q]) return;
      ++n;
      const double depth = sign * deviation[q];
      if (depth > first) {
        second = first;
        first = depth;
      } else if (depth > second) {
        second = depth;
      }
    };
    if (r > 0) take(k - cols);
    if (r + 1 < rows) take(k + cols);
    take(r * cols + (c + cols - 1) % cols);
    take(r * cols + (c + 1) % cols);
    if (n >= 2) out[k] = sign * std::min(sign * deviation[k], second);
  }
  return out;
}

}  // namespace rockface::tunnel
