#pragma once
// Small holes of a disparity map filled from their rims. Semi-global
// matching leaves speckled gaps on surfaces seen at a grazing angle (a
// tunnel's walls, roof and invert seen along the drive: the window sees the
// texture foreshortened differently in each view, and the uniqueness and
// left-right checks reject a pixel in three on some walls). Each gap left
// within a row or a column, no wider than a few pixels and bounded on both
// sides by disparities that agree with a plausible surface slope, is the
// same surface: it is filled by linear interpolation between its rims, as
// Hirschmuller's SGM fills its mismatches. A gap at an occlusion edge (rims
// apart by more than the slope allows) or wider than the limit stays empty.
#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct DisparityHoleFill {
  int max_gap_px = 8;         // longest run of unknown pixels filled (0 = none)
  double max_slope_px = 1.0;  // disparity change per pixel between the rims
};

// disparity: CV_32F, NaN = unknown; filled in place. Returns the number of
// pixels filled. A pixel filled along its row and its column takes the mean.
std::size_t fill_disparity_holes(cv::Mat& disparity, const DisparityHoleFill& fill);

}  // namespace rockface::photogrammetry
