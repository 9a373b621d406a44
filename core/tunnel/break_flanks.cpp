#include "core/tunnel/break_flanks.h"

#include <cmath>
#include <string>

#include "core/common/error.h"
#include "core/tunnel/developed_cells.h"

namespace rockface::tunnel {

std::vector<std::int8_t> follow_break_flanks(std::size_t rows, std::size_t cols,
                                             const std::vector<std::int8_t>& sign,
                                             const std::vector<double>& deviation,
                                             const std::vector<std::uint8_t>& valued) {
  const std::size_t n = rows * cols;
  if (sign.size() != n || deviation.size() != n || valued.size() != n)
    throw InputError("break flanks",
                     "one sign, deviation and valued flag per cell (" + std::to_string(n) + ")");
  std::vector<std::int8_t> out = sign;
  std::vector<std::size_t> stack;
  for (std::size_t k = 0; k < n; ++k)
    if (out[k] != 0) stack.push_back(k);
  while (!stack.empty()) {
    const std::size_t k = stack.back();
    stack.pop_back();
    for (std::size_t q : developed_neighbours(k, rows, cols)) {
      if (out[q] != 0 || !valued[q]) continue;
      const double d = deviation[q];
      if ((d > 0 ? 1 : -1) == out[k] && d != 0 && std::abs(d) <= std::abs(deviation[k])) {
        out[q] = out[k];
        stack.push_back(q);
      }
    }
  }
  return out;
}

}  // namespace rockface::tunnel
