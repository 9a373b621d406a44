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
                                               double noise_m) {
  std::vector<std::uint8_t> off(rows * cols, 0);
  const double diagonal = std::hypot(spacing.along_chainage_m, spacing.along_outline_m);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) {
      const std::size_t k = r * cols + c;
      if (!seen[k]) continue;
      bool supported = false;
      for (int dr = -1; dr <= 1 && !supported; ++dr)
        for (int dc = -1; dc <= 1 && !supported; ++dc) {
          if (dr == 0 && dc == 0) continue;
          const long rr = static_cast<long>(r) + dr;
          if (rr < 0 || rr >= static_cast<long>(rows)) continue;
          const std::size_t cc =
              dc < 0 ? (c + cols - 1) % cols : (c + static_cast<std::size_t>(dc)) % cols;
          const std::size_t n = static_cast<std::size_t>(rr) * cols + cc;
          if (!seen[n]) continue;
          const double distance = dr != 0 && dc != 0 ? diagonal
                                  : dr != 0          ? spacing.along_chainage_m
                                                     : spacing.along_outline_m;
          supported = std::abs(deviation[n] - deviation[k]) <= slope * distance + noise_m;
        }
      off[k] = supported ? 0 : 1;
    }
  return off;
}

}  // namespace rockface::tunnel
