#pragma once
// Dense matching of surfaces seen at a grazing angle (issue 38): a tunnel's
// walls, roof and invert seen along the drive change their disparity by
// 0.3-0.8 px per pixel. Semi-global matching's square windows and its
// penalties favour fronto-parallel surfaces: on such a slope the right
// image's window is squeezed or sheared against the left one, so SGBM
// follows it as terraces or leaves it unmatched (the sample heading's
// walls: 45 % of them matched, their terraces metres off along the ray).
//
// Each slanted pass matches the left image against the right image warped
// so that a surface of disparity slope (s along a row, t along a column)
// becomes fronto-parallel: R'(x', y) = R(xc + (1 - s)(x' - xc) - t (y - yc),
// y), (xc, yc) the image's centre. A pixel on such a surface has one
// disparity d' in the warped pair, and its disparity in the real pair is
// d = x - (xc + (1 - s)(x - d' - xc) - t (y - yc)). Each pass searches only
// the disparities that the first pass found on surfaces of about its slope.
//
// Per pixel, the result is the candidate (the first pass or a slanted one)
// whose own disparity map is flattest around it in its warped frame: the
// pass whose warp fits the surface there. A candidate is measured by its
// pass (left-right checked, cleaned as the first pass is), never
// interpolated, so an occluding edge stays an edge.
//
// match_rectified (dense_matching.h) runs them only on a tunnel's lining
// (preset.lining_along_the_drive, set where the 3D image is measured
// against a tunnel design), on the padded pair, moving the first pass's
// terraces too (max_change_px 3): on a face they changed the stepped face
// of FacetsOnReconstruction (a 1.1 m2 facet 28 deg off its set), so a face
// is matched as before (docs/accuracy-cost.md).
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace rockface::photogrammetry {

struct DisparitySlope {
  double along_row = 0;     // s: disparity change per pixel along a row
  double along_column = 0;  // t: per pixel down a column
};

struct SlantedPassOptions {
  // Walls (along the rows: the left wall -, the right +), invert (+, down
  // the columns) and roof (-): a tunnel seen along its drive from a base of
  // 1.4 m, 1.6-4 m from its walls, invert and roof (B / distance px per
  // px). Measured on the sample and D headings (docs/accuracy-cost.md):
  // these six cover what a seventh (+0.55, or a diagonal pair) would add
  // within 1 % of the lining.
  std::vector<DisparitySlope> slopes = {{-0.5, 0}, {-0.75, 0}, {0.3, 0},
                                        {0, 0.7},  {0, -0.4},  {0, 0.35}};
  int slope_step_px = 3;         // the local slope from disparities this far either side
  double slope_tolerance = 0.2;  // a first-pass pixel this near a pass's slope bounds its search
  // Fewer such pixels (of the image's) and the pass is not run, so a face
  // seen square costs no pass. The first pass matches little of a grazing
  // wall: at 2 % the D heading's walls ran too few passes (walls 78 -> 49 %
  // of their lining covered); 0.5 % runs all six there and on the sample.
  double min_fraction = 0.005;
  int max_disparities = 256;  // a pass's search range is capped here (a multiple of 16)
  // Where the first pass has a disparity, a slanted candidate replaces it
  // only within this many pixels: SGBM's terraces stand at most half a
  // riser (3-5 px) off the slope, while a candidate farther off is another
  // surface (on the stepped face, facets 28-45 deg off their set).
  double max_change_px = 3.0;
  // A candidate whose right pixel the first pass gives to a surface
  // nearer by more than this (px of disparity) is occluded there.
  double occlusion_px = 1.0;
  double first_pass_bias = 0.05;  // a slanted pass wins over the first by this much slope
};

// The disparity search of one pass: [min, min + num).
struct SlantedRange {
  int min_disparity = 0, num_disparities = 0;
};

// One pass's matcher: the left image against `right_warped` over `range`,
// returning disparities (CV_32F, NaN = none) in the warped frame.
using PassMatcher = std::function<cv::Mat(const cv::Mat& right_warped, const SlantedRange& range)>;

struct SlantedResult {
  cv::Mat disparity;        // CV_32F, NaN = unknown, in the real pair
  std::size_t slanted = 0;  // pixels taken from a slanted pass
  int passes_run = 0;
};

// first: the first pass's disparities (CV_32F, NaN = unknown) over `right`.
SlantedResult match_slanted(const cv::Mat& right, const cv::Mat& first,
                            const SlantedPassOptions& options, const PassMatcher& matcher);

// The right image warped for a slope (above); exposed for tests.
cv::Mat warp_for_slope(const cv::Mat& right, const DisparitySlope& slope);

}  // namespace rockface::photogrammetry
