#pragma once
// What the synthetic mock camera renders, as plain values: the `imaging`
// section of a scene (SCENE.md) with the surface patches and the joints it
// draws. The camera part does not read scene files (storage does); the
// command line converts a parsed scene into this.
//
// Coordinates are in one local frame (x = East, y = North, z = Up, metres),
// normally the scene's datum-relative frame, so that survey coordinates of
// 10^6 m lose no precision in single-precision depth and texture lookups.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::camera {

// One planar piece of the free surface.
struct SyntheticPatch {
  std::string id;
  std::vector<Eigen::Vector3d> polygon;  // at least 3 points, planar
};

// A joint plane, drawn as a dark trace where it cuts the surface.
struct SyntheticJoint {
  std::string id;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

// Looks from `position` at `look_at` without roll: image x horizontal
// (pointing right), image up toward +z.
struct SyntheticStation {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d look_at = Eigen::Vector3d::UnitY();
};

// A vertical range pole with two circular targets. `base` is the centre of
// the lower target and the upper target's centre is `length` above it, so
// the distance between the two target centres is exactly `length`. (Place
// the base at least half a target diameter above the ground.)
struct SyntheticRangePole {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  double length = 2.0;            // m
  double target_diameter = 0.25;  // m
};

// Imaging effects; each is off unless the scene switches it on.
struct SyntheticEffects {
  bool distortion = false;  // render through the camera's Brown distortion
  double noise_sigma = 0;   // Gaussian sensor noise, grey levels (0..255)
  double blur_px = 0;       // Gaussian blur sigma, pixels
  double exposure = 1.0;    // gain on the rendered radiance
};

struct SyntheticScene {
  std::vector<SyntheticPatch> patches;
  std::vector<SyntheticJoint> joints;        // only joints with a point
  photogrammetry::CameraIntrinsics camera;   // distortion used only with effects.distortion
  std::array<SyntheticStation, 2> stations;  // left, right
  std::optional<SyntheticRangePole> range_pole;
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> reference_line;  // from, to
  SyntheticEffects effects;
  unsigned texture_seed = 7;
};

// World-to-camera pose of a station (OpenCV axes: z forward, x right, y
// down). Throws InputError naming `where` when the station looks straight
// up or down (no horizontal image x-axis) or at its own position.
photogrammetry::CameraPose station_pose(const SyntheticStation& station, const std::string& where);

}  // namespace rockface::camera
