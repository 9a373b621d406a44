#pragma once
// Least-squares area matching of tie points. SIFT locates a keypoint where
// its scale-space blob peaks; when the two views foreshorten a slanted facet
// differently, that peak shifts between the views by a few tenths of a pixel
// in the same direction all over the facet - a bias that does not average
// out and tilts the relative orientation. Re-locating the right point by
// affine image alignment (OpenCV's ECC, cv::findTransformECC) of a window
// around the fixed left point removes it, as classic photogrammetric
// least-squares matching does.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/common/progress.h"

namespace rockface::photogrammetry {

struct TiePointRefinementOptions {
  int half_window_px = 12;       // window (2h+1)^2 around the left point, full-size pixels
  double max_shift_px = 2.0;     // farther than this from the SIFT position: a wrong match
  double min_correlation = 0.8;  // ECC's normalised correlation at convergence
  int neighbours = 12;           // tie points that give the initial local affine map
};

struct TiePointRefinementStats {
  int refined = 0, rejected = 0;
  double median_shift_px = 0;
};

// Refines `right` in place for each pair; pairs that do not converge are
// removed from both lists. Images: 8-bit grey, full size.
TiePointRefinementStats refine_tie_points(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                          std::vector<Eigen::Vector2d>& left,
                                          std::vector<Eigen::Vector2d>& right,
                                          const TiePointRefinementOptions& options,
                                          Progress& progress);

}  // namespace rockface::photogrammetry
