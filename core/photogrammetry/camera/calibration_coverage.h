#pragma once
// How much of the image a calibration's views saw (issue 42). Lens
// distortion grows with the distance from the image centre, and the Brown
// model's higher terms (k2 r^4, k3 r^6) are fitted only out to the farthest
// corner a view showed: beyond it they extrapolate freely (central views
// only gave k2 5.5, k3 -112 on the virtual camera, a lens that bends the
// image's corners by metres of pixels). A calibration whose views leave the
// image's edges unseen is usable near the centre, not across the frame, and
// the user is told so and which part of the image to cover.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/calibration.h"

namespace rockface::photogrammetry {

struct CalibrationCoverage {
  // The farthest pattern point from the image centre, as a fraction of the
  // half-diagonal (1: a point in the very corner).
  double radius_fraction = 0;
  // Of a 3 x 3 grid over the image, the cells with a pattern point, and
  // the names of those without ("top left", "left", ...).
  int cells_seen = 0;
  std::vector<std::string> unseen_cells;

  // Below these the distortion at the image's edges is extrapolated. 70 %
  // of the half-diagonal lies between real views known to calibrate well
  // (OpenCV's chessboard sample reaches 73 % and matches its reference)
  // and central views known to fail at the corners (46 %: 47 px off there,
  // tests/core/photogrammetry/camera/calibration_test.cpp); on a 3:2
  // sensor it is the outer sixth of the width. A cell of the 3 x 3 grid
  // never seen leaves that side's distortion to the polynomial.
  static constexpr double kMinRadiusFraction = 0.7;
  static constexpr int kMinCellsSeen = 7;
  bool poor() const { return radius_fraction < kMinRadiusFraction || cells_seen < kMinCellsSeen; }
  // What to tell the user when poor(): what was seen and what to add.
  std::string warning() const;
};

// The coverage of the views a calibration kept (outliers left out), in an
// image of `size`. `result.views` are in the order of `views`.
CalibrationCoverage calibration_coverage(const std::vector<CalibrationView>& views,
                                         const CalibrationResult& result, cv::Size size);

}  // namespace rockface::photogrammetry
