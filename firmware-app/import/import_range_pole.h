#pragma once
// The range pole on a cloud in a local frame (`rockface import --frame local
// --pole X1,Y1,Z1,X2,Y2,Z2`, issue 43): a scanner's or a drone's cloud that
// saw the pole standing at the face is scaled and levelled by its two
// targets, and turned to north by a compass line when one is given, as a
// photographed visit is (core/photogrammetry/estimators/registration.h):
// the pole's targets `length_m` apart, the pole vertical, the lower target at
// the origin; without a compass line the view's optical axis is taken as
// north-ish, as the left camera's is.
//
// The targets and the line's ends are points of the cloud in its own
// coordinates (as picked in CloudCompare, or tapped on the import's view),
// lower target first.
#include <optional>

#include <Eigen/Core>

#include "core/photogrammetry/estimators/registration.h"

namespace rockface::app {

struct ImportPole {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero(), upper = Eigen::Vector3d::Zero();
};

// A line of the cloud whose compass bearing the geologist measured.
struct ImportCompassLine {
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
  double azimuth_deg = 0, declination_deg = 0;  // declination east positive
};

struct ImportPoleRegistration {
  photogrammetry::Similarity transform;      // the cloud's frame -> the project's
  std::optional<double> north_rotation_deg;  // about the vertical, when a compass line turned it
};

// camera_to_cloud: the virtual view's camera (camera axes -> the cloud's
// frame). Throws InputError naming the option: the targets at one point, a
// length outside (0, 50] m, a compass line that is (nearly) vertical.
ImportPoleRegistration register_import_to_pole(const ImportPole& pole, double length_m,
                                               const std::optional<ImportCompassLine>& north,
                                               const photogrammetry::Similarity& camera_to_cloud);

}  // namespace rockface::app
