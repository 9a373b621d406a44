#pragma once
// Rectification and dense matching: the oriented pair is rectified
// (cv::stereoRectify), matched by semi-global matching (cv::StereoSGBM) at the
// preset's image scale with sub-pixel disparities, checked left against right
// (a second SGBM on the mirrored pair gives the right disparity), cleaned
// of untextured pixels (texture_mask.h) and speckles (cv::filterSpeckles),
// its terraces smoothed into their slope (disparity_terraces.h) and its
// small holes filled from their rims (disparity_holes.h). A tunnel's lining
// (preset.lining_along_the_drive) is matched on the padded pair and again by
// slanted passes (slanted_passes.h).
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/estimators/relative_orientation.h"
#include "core/photogrammetry/reconstruction/preset.h"

namespace rockface::photogrammetry {

// Disparities of a rectified pair: float, pixels, NaN where unknown.
// x_right = x_left - d.
struct DisparityRange {
  int min_disparity = 0;
  int num_disparities = 64;  // a multiple of 16
};

struct DisparityMap {
  cv::Mat disparity;  // CV_32F, NaN = no valid match
  DisparityRange range;
  double valid_fraction = 0;        // of all pixels
  double lr_rejected_fraction = 0;  // of the pixels SGBM matched, removed by the left-right check
  // of the pixels SGBM matched, removed where the left image has no texture
  // (texture_mask.h); left-right rejected ones included
  double untextured_fraction = 0;
  // of all pixels, filled between the rims of a small hole (disparity_holes.h);
  // not in valid_fraction
  double filled_fraction = 0;
  // of all pixels, moved from a terrace onto its slope (disparity_terraces.h)
  double terraced_fraction = 0;
};

// Matches a rectified pair (8-bit grey or BGR, same size) over `range`.
// texture_left: the left image whose texture is checked (texture_mask.h),
// when `left` is not it (brightness-normalised views lift the background's
// noise to the rock's level); empty = `left`.
DisparityMap match_rectified(const cv::Mat& left, const cv::Mat& right, const DisparityRange& range,
                             const ReconstructionPreset& preset, Progress& progress,
                             const cv::Mat& texture_left = cv::Mat());

// The rectification of an oriented pair at a working scale.
struct Rectification {
  double scale = 1;    // of the rectified images relative to the originals
  cv::Size size;       // rectified image size
  cv::Matx33d R1, R2;  // rotation from each original camera into its rectified frame
  cv::Matx34d P1, P2;  // rectified projections
  cv::Matx44d Q;       // disparity to depth (OpenCV's convention)
  cv::Mat map1x, map1y, map2x, map2y;  // remap tables (CV_32F), originals -> rectified
  double focal_px() const { return P1(0, 0); }
  double base() const { return -P2(0, 3) / P2(0, 0); }  // model units (|t| = 1 model)
};

Rectification rectify(const CameraIntrinsics& left, const CameraIntrinsics& right,
                      const RelativeOrientation& ro, double scale);

// The tie points of the orientation (ro.left / ro.right, full-size pixels)
// in the pixels of the rectified images.
struct RectifiedTiePoints {
  std::vector<Eigen::Vector2d> left, right;
};
RectifiedTiePoints rectified_tie_points(const RelativeOrientation& ro, const Rectification& rect,
                                        const CameraIntrinsics& left,
                                        const CameraIntrinsics& right);

// The disparity search range from the sparse inliers, widened by the preset's
// margin and capped at preset.max_disparities around the median.
DisparityRange disparity_range_from_inliers(const RelativeOrientation& ro,
                                            const Rectification& rect, const CameraIntrinsics& left,
                                            const CameraIntrinsics& right,
                                            const ReconstructionPreset& preset);

}  // namespace rockface::photogrammetry
