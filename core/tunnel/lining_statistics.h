#pragma once
// Robust figures of the excavated surface on the developed view (issue 38):
// a reconstruction's mesh holds noise, a bias of its surface and stray
// triangles (holes in the invert through which a ray meets something far
// below, specks off the wall), and the round's maximum or its volumes must
// not be made of them.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rockface::tunnel {

// The median of the values (their order is changed); NaN when empty.
double median_of(std::vector<double>& values);

// The lining's offset from the design as a whole: the median normal
// deviation of the seen cells and its standard error (1.2533 x the robust
// sigma, 1.4826 x the median absolute deviation, over the square root of the
// count; the cells' errors taken as independent). Read as the
// reconstruction's bias where the breaks cover less than half the lining.
struct LiningOffset {
  double median_m = 0;
  double standard_error_m = 0;
  double robust_sigma_m = 0;  // of the cells about the median
  std::size_t cells = 0;
};
LiningOffset lining_offset(std::span<const double> deviations);

// Cells off any plausible lining. Two seen cells agree when their
// deviations differ by less than `slope` x their distance on the developed
// view plus `noise_m`; agreeing 8-neighbours join into pieces of surface. A
// surface, even one with a step where a block fell out, continues into at
// least one neighbour; a stray triangle or a speck of noise does not. So a
// cell that agrees with none of its seen neighbours (or has none) is off
// the lining, and so is a piece smaller than `max_island_m2` that meets
// other seen cells only across a jump: a cluster of stray triangles seen
// through a hole of the wall (issue 38: the D heading's 2-3 cells 0.85 m
// behind the wall, whose interpolated neighbours added 0.07 m3 of
// overbreak). `deviation` is row-major rows x cols (the arc length wraps),
// `seen` says which cells hold a value; returns one flag per cell.
struct NeighbourSpacing {
  double along_chainage_m = 0, along_outline_m = 0;
};
std::vector<std::uint8_t> cells_off_the_lining(std::size_t rows, std::size_t cols,
                                               std::span<const double> deviation,
                                               std::span<const std::uint8_t> seen,
                                               const NeighbourSpacing& spacing, double slope,
                                               double noise_m, double max_island_m2);

}  // namespace rockface::tunnel
