#pragma once
// Whether a patch of the developed view's counted cells is a break or the
// reconstruction's noise (issue 38). Each cell's noise threshold comes from
// its predicted depth precision (lining_precision.h), which knows the
// cameras' geometry but not the photographs' texture: where the rock is
// poorly textured the dense matching is noisier than predicted (on the
// second test heading's roof and invert 1.5-2.5 times, docs/accuracy-cost.md)
// and its errors, correlated over the matching window, pass the threshold in
// blobs as wide as the patch rule's rectangle. Such a blob is as deep as the
// lining around it is rough; a break is deeper. So a patch counts only when
// its mean depth lies beyond noise_sigmas times the larger of its cells'
// predicted sigma and the spread measured on the lining around it (the
// valued cells within ring_m that no patch holds, robust: 1.4826 times their
// median absolute deviation from their median).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace rockface::tunnel {

struct BreakSignificanceOptions {
  double noise_sigmas = 2;
  std::size_t ring_rows = 4;   // the lining around a patch: this many sections
  std::size_t ring_cols = 20;  // and rays on each side of each of its cells
  // Fewer cells of lining around a patch than this: its predicted sigma
  // alone (nothing to measure a spread on).
  std::size_t min_ring_cells = 30;
};

// What was decided for one patch of cells of one sign.
struct PatchSignificance {
  int sign = 0;
  std::size_t cells = 0;
  double mean_depth_m = 0;             // mean |deviation| over its cells
  double predicted_sigma_m = 0;        // mean predicted sigma over its cells
  std::optional<double> ring_sigma_m;  // the lining around it, when measurable
  bool counts = false;
};

// sign: per cell (row-major, rows x cols; rows are sections, columns rays
// round the outline, which wraps) +1 overbreak, -1 underbreak, 0 none, the
// patches that passed the patch rule (break_patches.h). deviation: per cell,
// m (the lining's offset removed), read where valued. sigma: per cell, its
// predicted depth sigma (m). Returns the signs of the patches that count;
// `decided`, when given, gets one entry per patch.
std::vector<std::int8_t> significant_breaks(std::size_t rows, std::size_t cols,
                                            const std::vector<std::int8_t>& sign,
                                            const std::vector<double>& deviation,
                                            const std::vector<std::uint8_t>& valued,
                                            const std::vector<double>& sigma,
                                            const BreakSignificanceOptions& options,
                                            std::vector<PatchSignificance>* decided = nullptr);

}  // namespace rockface::tunnel
