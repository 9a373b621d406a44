#pragma once
// Ground control on monitoring targets. A control point picked on a
// circular target (the tunnel surveyor's: a white disk in a black ring) is
// measured on the target itself: found in both photographs, its centre
// located to a tenth of a pixel and triangulated, as the range pole's are.
// Read from the 3D image at the pick instead, it carries the dense
// matching's depth error there (5-25 mm at 8 m at the tablet's
// resolution): a few metres between the points turn the model by tenths of
// a degree, and a tunnel round's over- and underbreak volumes move by tens
// of percent for a quarter of a degree (issue 38).
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/estimators/relative_orientation.h"
#include "core/photogrammetry/targets/target_pair.h"

namespace rockface::photogrammetry {

struct ControlTargetOptions {
  // How far (left image pixels) a pick may lie from its target's centre:
  // inside the target's own disk (a tap on it), or this much for a target
  // only a few pixels across. A natural point (a trace's end) beside a
  // target is not taken for it.
  double min_search_px = 10;
};

// For each pick (left image pixels, distorted): the target whose left
// centre lies nearest it within the search distance, with its partner on
// the epipolar line in the right image, triangulated (model frame: left
// camera, base 1). Nothing for a pick with no target there: the caller
// reads that point from the surface.
std::vector<std::optional<TargetPair>> measure_control_targets(
    const cv::Mat& left_image, const cv::Mat& right_image, const CameraIntrinsics& left,
    const CameraIntrinsics& right, const RelativeOrientation& ro,
    const std::vector<Eigen::Vector2d>& picks, const ControlTargetOptions& options = {});

}  // namespace rockface::photogrammetry
