#pragma once
// The terraces of semi-global matching smoothed back into the slope they
// stand for (issue 38). A surface seen at a grazing angle (a tunnel's
// walls, roof and invert seen along the drive) changes its disparity by
// 0.5-0.8 px per pixel; SGBM's penalties and its square windows follow it
// as a staircase instead: flat treads a few pixels long and risers of
// 3-5 px between them. The treads lie off the surface (a depth error of
// half a riser, centimetres normal to the wall), and the lattice mesh cuts
// every riser as an occlusion edge, so the walls come out in strips.
// Along a row (and then a column), a run of at least `min_treads` short
// treads whose risers all climb the same way, each no higher than
// `max_riser_px`, is a staircase: its values between the first tread's
// centre and the last one's are replaced by the straight lines through the
// treads' centres (the middle of a tread is where its flat value meets the
// slope). A long flat run, a step higher than the limit (an occlusion edge)
// or risers that change direction (noise, relief) are left as they are.
#include <cstddef>

#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct TerraceSmoothing {
  int max_tread_px = 16;      // longest run between two risers taken as a tread (0 = off)
  double max_riser_px = 6.0;  // highest step between treads of one staircase
  double min_riser_px = 1.0;  // a step between neighbouring pixels of at least this is a riser
  int min_treads = 3;         // fewest treads that make a staircase
};

// disparity: CV_32F, NaN = unknown; smoothed in place, rows first, then
// columns. Returns the number of pixels whose value changed.
std::size_t smooth_disparity_terraces(cv::Mat& disparity, const TerraceSmoothing& smoothing);

}  // namespace rockface::photogrammetry
