#include "core/tunnel/lining_interpolation.h"

#include <algorithm>
#include <cmath>

namespace rockface::tunnel {

namespace {

// One direction's estimate at a cell: linear between the measured cells
// that bracket it within the widest hole allowed.
struct Bracket {
  bool found = false;
  double normal = 0, ray = 0;
  double lo = 0, hi = 0;  // the measured ends' normal deviations
  double hole_m = 0;
};

Bracket bracket(std::size_t a, std::size_t b, std::size_t steps_a, std::size_t steps_b,
                std::span<const double> normal, std::span<const double> ray, double spacing) {
  Bracket out;
  out.found = true;
  const double t = static_cast<double>(steps_a) / static_cast<double>(steps_a + steps_b);
  out.normal = normal[a] + t * (normal[b] - normal[a]);
  out.ray = ray[a] + t * (ray[b] - ray[a]);
  out.lo = std::min(normal[a], normal[b]);
  out.hi = std::max(normal[a], normal[b]);
  out.hole_m = static_cast<double>(steps_a + steps_b - 1) * spacing;
  return out;
}

}  // namespace

std::vector<FilledCell> fill_lining_holes(std::size_t rows, std::size_t cols,
                                          std::span<const double> normal,
                                          std::span<const double> ray,
                                          std::span<const std::uint8_t> measured,
                                          std::span<const std::uint8_t> fillable,
                                          const NeighbourSpacing& spacing, double max_hole_m) {
  std::vector<FilledCell> out;
  if (!(max_hole_m > 0) || rows == 0 || cols == 0) return out;
  // The most unmeasured cells a hole may hold in each direction.
  const auto limit = [&](double step) {
    return step > 0 ? static_cast<std::size_t>(std::floor(max_hole_m / step + 1e-9)) : 0;
  };
  const std::size_t max_along_s = std::min(limit(spacing.along_outline_m), cols - 1);
  const std::size_t max_along_c = limit(spacing.along_chainage_m);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) {
      const std::size_t k = r * cols + c;
      if (measured[k] || !fillable[k]) continue;
      // The nearest measured cell on each side, no farther than a hole allows.
      Bracket along_s, along_c;
      {
        std::size_t back = 1, ahead = 1;
        while (back <= max_along_s && !measured[r * cols + (c + cols - back) % cols]) ++back;
        while (ahead <= max_along_s && !measured[r * cols + (c + ahead) % cols]) ++ahead;
        if (back <= max_along_s && ahead <= max_along_s && back + ahead - 1 <= max_along_s)
          along_s = bracket(r * cols + (c + cols - back) % cols, r * cols + (c + ahead) % cols,
                            back, ahead, normal, ray, spacing.along_outline_m);
      }
      {
        std::size_t back = 1, ahead = 1;
        while (back <= max_along_c && back <= r && !measured[(r - back) * cols + c]) ++back;
        while (ahead <= max_along_c && r + ahead < rows && !measured[(r + ahead) * cols + c])
          ++ahead;
        if (back <= max_along_c && back <= r && ahead <= max_along_c && r + ahead < rows &&
            back + ahead - 1 <= max_along_c)
          along_c = bracket((r - back) * cols + c, (r + ahead) * cols + c, back, ahead, normal, ray,
                            spacing.along_chainage_m);
      }
      if (!along_s.found && !along_c.found) continue;
      FilledCell f;
      f.cell = k;
      // The narrower hole is the surer estimate: weights 1 / (hole + a cell).
      const double ws = along_s.found ? 1 / (along_s.hole_m + spacing.along_outline_m) : 0;
      const double wc = along_c.found ? 1 / (along_c.hole_m + spacing.along_chainage_m) : 0;
      f.normal_m = (ws * along_s.normal + wc * along_c.normal) / (ws + wc);
      f.ray_m = (ws * along_s.ray + wc * along_c.ray) / (ws + wc);
      double lo = std::min(along_s.found ? along_s.lo : along_c.lo,
                           along_c.found ? along_c.lo : along_s.lo);
      double hi = std::max(along_s.found ? along_s.hi : along_c.hi,
                           along_c.found ? along_c.hi : along_s.hi);
      f.sigma_m = 0.5 * (hi - lo);
      f.hole_m =
          std::max(along_s.found ? along_s.hole_m : 0.0, along_c.found ? along_c.hole_m : 0.0);
      out.push_back(f);
    }
  return out;
}

}  // namespace rockface::tunnel
