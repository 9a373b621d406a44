#pragma once
// Calibration of one camera body + lens + focal setting from several views of
// a planar pattern (chessboard or symmetric circle grid), with OpenCV and the
// Brown model (k1, k2, p1, p2, k3).
//
// Views whose reprojection error stands far above the others (a blurred
// shot, a board that moved, corners detected in the wrong order) are
// reported as outliers and left out of the final solution; the result keeps
// every view's error so the user sees which shots to retake.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::photogrammetry {

struct CalibrationPattern {
  enum class Kind { chessboard, circles };
  Kind kind = Kind::chessboard;
  int cols = 0, rows = 0;  // inner corners (chessboard) or circles (grid)
  double spacing_m = 0;    // square size or circle centre spacing, metres

  cv::Size size() const { return {cols, rows}; }
  // Pattern points in the board plane (z = 0), metres, in detection order.
  std::vector<cv::Point3f> board_points() const;
};

// Parses "chessboard:COLSxROWS:SQUARE_M" or "circles:COLSxROWS:SPACING_M".
// Throws InputError("--pattern", ...) naming what is wrong.
CalibrationPattern parse_calibration_pattern(std::string_view spec);

// The pattern found in one image, sub-pixel refined; nullopt when the whole
// pattern is not visible.
std::optional<std::vector<cv::Point2f>> detect_calibration_pattern(
    const cv::Mat& grey, const CalibrationPattern& pattern);

struct CalibrationView {
  std::string name;  // file name or label, for reports
  std::vector<cv::Point2f> image_points;
};

struct CalibrationOptions {
  // A view is an outlier when its RMS error exceeds both this factor times
  // the median view RMS and `outlier_min_px`: a sharp, well-detected board
  // reprojects to a few tenths of a pixel, a bad view to pixels.
  double outlier_factor = 3.0;
  double outlier_min_px = 1.0;
  int min_views = 3;  // fewer views leave focal length and distortion unresolved
};

struct CalibrationViewResult {
  std::string name;
  double rms_px = 0;      // RMS reprojection error of this view's points
  bool outlier = false;   // left out of the final solution
  CameraPose board_pose;  // board-to-camera: x_cam = R (x_board - centre)
};

struct CalibrationResult {
  CameraIntrinsics intrinsics;               // rms_px set to the final RMS
  double rms_px = 0;                         // over all points of the views kept
  std::vector<CalibrationViewResult> views;  // in input order, outliers included
  int views_used() const;
  std::vector<std::string> outlier_names() const;
};

// Calibrates from detected views of one pattern, all of image size `size`.
// Throws InputError("calibration", ...) when fewer than options.min_views
// views remain.
CalibrationResult calibrate_camera(const std::vector<CalibrationView>& views,
                                   const CalibrationPattern& pattern, cv::Size size,
                                   const CalibrationOptions& options = {});

// What happened to each image file given to calibrate_from_images.
struct CalibrationImageReport {
  std::string path;
  bool pattern_found = false;
};

struct CalibrationFromImages {
  CalibrationResult result;
  std::vector<CalibrationImageReport> images;  // in input order
  // The views the pattern was found in (result.views' order) and the
  // images' size: what calibration_coverage reads.
  std::vector<CalibrationView> views;
  cv::Size size;
};

// Loads the images, detects the pattern and calibrates. Throws InputError
// naming the file for an unreadable or corrupt image or one of another size,
// and naming the images without a detected pattern when too few views remain.
CalibrationFromImages calibrate_from_images(const std::vector<std::string>& paths,
                                            const CalibrationPattern& pattern,
                                            const CalibrationOptions& options = {});

}  // namespace rockface::photogrammetry
