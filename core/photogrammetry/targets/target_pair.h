#pragma once
// One circular target seen in both photographs: its right observation found
// on the left one's epipolar line, the circle's plane normal chosen where
// the two views agree, and its centre triangulated. Shared by the range
// pole's two targets and the monitoring targets of ground control.
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/estimators/relative_orientation.h"
#include "core/photogrammetry/targets/circular_target.h"

namespace rockface::photogrammetry {

struct TargetPair {
  TargetObservation left, right;  // centre_px: the corrected centre of the chosen normal
  Eigen::Vector3d model = Eigen::Vector3d::Zero();  // left camera frame, base 1
  double epipolar_px = 0;  // the corrected centres' distance from each other's epipolar line
};

// Epipolar tolerance for a pair of corrected centres: the centres are
// sub-pixel, the relative orientation good to about a pixel at the border.
inline constexpr double kTargetEpipolarPx = 4.0;

// Pixels between the right observation's centre and the epipolar line of
// the left one's (each the mean of its two candidate centres).
double target_epipolar_px(const TargetObservation& left, const TargetObservation& right,
                          const RelativeOrientation& ro, double focal_px);

// The index in `right` of `left`'s partner: on its epipolar line within
// `max_px`, of a similar size (half to twice its white disk), in front of
// both cameras, nearest the line; -1 when none. `err` gets its distance.
int epipolar_partner(const TargetObservation& left, const std::vector<TargetObservation>& right,
                     const RelativeOrientation& ro, double focal_px, double max_px, double& err);

// The pair triangulated: of the 2 x 2 candidate normals, the pair where the
// views agree (the right normal turned into the left frame); the centres
// corrected for that normal.
TargetPair triangulate_target_pair(TargetObservation left, TargetObservation right,
                                   const CameraIntrinsics& left_camera,
                                   const CameraIntrinsics& right_camera,
                                   const RelativeOrientation& ro);

}  // namespace rockface::photogrammetry
