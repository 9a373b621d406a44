#include "core/tunnel/break_significance.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/error.h"
#include "core/tunnel/developed_cells.h"

namespace rockface::tunnel {

namespace {

// The robust spread of `values` (reordered): 1.4826 times the median
// absolute deviation from the median, sigma for normal errors.
double robust_spread(std::vector<double>& values) {
  auto median = [](std::vector<double>& v) {
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
  };
  const double m = median(values);
  for (double& v : values) v = std::abs(v - m);
  return 1.4826 * median(values);
}

}  // namespace

std::vector<std::int8_t> significant_breaks(std::size_t rows, std::size_t cols,
                                            const std::vector<std::int8_t>& sign,
                                            const std::vector<double>& deviation,
                                            const std::vector<std::uint8_t>& valued,
                                            const std::vector<double>& sigma,
                                            const BreakSignificanceOptions& options,
                                            std::vector<PatchSignificance>* decided) {
  const std::size_t n = rows * cols;
  if (sign.size() != n || deviation.size() != n || valued.size() != n || sigma.size() != n)
    throw InputError("break significance", "one sign, deviation, valued flag and sigma per cell (" +
                                               std::to_string(n) + ")");
  if (decided) decided->clear();
  std::vector<std::int8_t> kept(n, 0);
  std::vector<std::uint8_t> labelled(n, 0);
  // Marks of the ring cells already taken for the current patch.
  std::vector<std::size_t> ring_mark(n, 0);
  std::size_t patch_number = 0;
  std::vector<std::size_t> patch;
  std::vector<double> ring;
  for (std::size_t start = 0; start < n; ++start) {
    if (sign[start] == 0 || labelled[start]) continue;
    ++patch_number;
    // The patch: 4-connected cells of its sign, the outline wrapping.
    patch.assign(1, start);
    labelled[start] = 1;
    for (std::size_t i = 0; i < patch.size(); ++i) {
      for (std::size_t q : developed_neighbours(patch[i], rows, cols))
        if (!labelled[q] && sign[q] == sign[start]) {
          labelled[q] = 1;
          patch.push_back(q);
        }
    }
    PatchSignificance p;
    p.sign = sign[start];
    p.cells = patch.size();
    for (std::size_t k : patch) {
      p.mean_depth_m += std::abs(deviation[k]);
      p.predicted_sigma_m += sigma[k];
    }
    p.mean_depth_m /= static_cast<double>(patch.size());
    p.predicted_sigma_m /= static_cast<double>(patch.size());
    // The lining around it: valued cells no patch holds within the ring.
    ring.clear();
    for (std::size_t k : patch)
      for_developed_rectangle(k / cols, k % cols, rows, cols, options.ring_rows, options.ring_cols,
                              [&](std::size_t q) {
                                if (ring_mark[q] == patch_number || !valued[q] || sign[q] != 0)
                                  return;
                                ring_mark[q] = patch_number;
                                ring.push_back(deviation[q]);
                              });
    double noise = p.predicted_sigma_m;
    if (ring.size() >= options.min_ring_cells) {
      p.ring_sigma_m = robust_spread(ring);
      noise = std::max(noise, *p.ring_sigma_m);
    }
    p.counts = p.mean_depth_m > options.noise_sigmas * noise;
    if (p.counts)
      for (std::size_t k : patch) kept[k] = sign[k];
    if (decided) decided->push_back(p);
  }
  return kept;
}

}  // namespace rockface::tunnel
