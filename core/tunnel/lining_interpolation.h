#pragma once
// Unseen cells of the developed view filled from their measured neighbours
// (issue 38): a photographed round's 3D image leaves holes in the lining
// (grazing walls, occluded strips behind ribs of rock), and a volume summed
// over the measured cells alone reads low by the holes' share. A hole no
// wider than a stated limit that measured cells bracket along the outline
// or along the chainage is filled by linear interpolation between them
// (both directions' estimates weighted by the inverse of their hole's
// width); nothing is extrapolated past the measured stretch, nothing is
// filled across a wider hole, and each filled cell carries an uncertainty.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/tunnel/lining_statistics.h"

namespace rockface::tunnel {

struct FilledCell {
  std::size_t cell = 0;  // row-major index
  double normal_m = 0;   // the interpolated normal deviation
  double ray_m = 0;      // and ray deviation
  // One sigma of the interpolation: half the spread of the measured cells
  // it rests on and of the directions' estimates (a hole between cells that
  // disagree is uncertain by their disagreement). The reconstruction's own
  // depth sigma is the caller's to add.
  double sigma_m = 0;
  double hole_m = 0;  // width of the widest hole it was filled across
};

// rows x cols cells, row-major; the outline (columns) wraps, the chainage
// (rows) does not. `measured`: cells holding a value; `fillable`: cells
// that may be filled (unseen ones). A hole is the run of unmeasured cells
// between two measured ones; its width is its cell count times the spacing.
// max_hole_m <= 0 fills nothing.
std::vector<FilledCell> fill_lining_holes(std::size_t rows, std::size_t cols,
                                          std::span<const double> normal,
                                          std::span<const double> ray,
                                          std::span<const std::uint8_t> measured,
                                          std::span<const std::uint8_t> fillable,
                                          const NeighbourSpacing& spacing, double max_hole_m);

}  // namespace rockface::tunnel
