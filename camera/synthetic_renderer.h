#pragma once
// The synthetic mock camera's renderer: ray casting of a SyntheticScene
// through the pinhole + Brown model, one ray per pixel centre.
//
// What is drawn:
// - surface patches with a rock texture in world coordinates, lit by a lamp
//   at the stations (a headlamp in a tunnel);
// - every joint as a dark trace 2 cm wide on the surface where its plane
//   cuts a patch (anti-aliased over the pixel footprint);
// - the range pole: a red and white banded vertical pole (4 cm across) and
//   two circular targets, each a black disk of the target diameter with a
//   white disk of half that diameter at its centre. A target disk faces the
//   midpoint of the two stations (its normal points from the target centre
//   to that midpoint), so both cameras see it nearly face-on. Its edges are
//   anti-aliased over the pixel footprint.
// - the survey's monitoring targets (scene control_targets): drawn as the
//   pole's targets are, each of its own diameter, facing the same midpoint.
// - nothing hit: a dark background (tunnel darkness).
//
// Deterministic: the same scene gives the same pixels bit for bit (integer
// lattice hashes, fixed-seed cv::RNG for noise, rows rendered independently).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "camera/synthetic_scene.h"
#include "core/common/progress.h"
#include "core/photogrammetry/camera/camera_model.h"

namespace rockface::camera {

// Widths of what is drawn, metres.
struct SyntheticDrawing {
  static constexpr double kTraceWidth = 0.02;
  static constexpr double kPoleRadius = 0.02;
  static constexpr double kPoleBand = 0.1;  // red and white bands
};

struct SyntheticView {
  cv::Mat image;  // CV_8UC3 (BGR)
  cv::Mat
      depth;  // CV_32F depth along the optical axis, metres, 0 = nothing hit; empty unless asked
  photogrammetry::CameraPose pose;
};

// The intrinsics the renderer really used: the scene's camera, without
// distortion unless effects.distortion is on.
photogrammetry::CameraIntrinsics rendered_intrinsics(const SyntheticScene& scene);

// Renders station 0 (left) or 1 (right) with `camera` (normally
// rendered_intrinsics(scene); a scaled camera for live-view frames).
SyntheticView render_view(const SyntheticScene& scene, int station,
                          const photogrammetry::CameraIntrinsics& camera, bool with_depth,
                          Progress& progress);

struct TargetTruth {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // world
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // disk normal, toward the stations
  // Projection of the true 3-D centre (distortion included), not the centre
  // of the imaged ellipse, which lies slightly off it under perspective.
  std::array<Eigen::Vector2d, 2> image{Eigen::Vector2d::Zero(),
                                       Eigen::Vector2d::Zero()};  // left, right
  std::array<bool, 2> visible{};                                  // inside the image and not hidden
};

struct TraceTruth {
  std::string joint, patch;
  std::array<Eigen::Vector3d, 2> world;     // the straight segment on the patch
  std::vector<Eigen::Vector2d> left_image;  // densely sampled, distortion included;
                                            // not clipped to the image, not occlusion-culled
};

// Where each joint (with a point) cuts each surface patch: the true traces,
// as straight world segments (datum-relative like the scene).
struct TraceSegment {
  std::string joint, patch;
  std::array<Eigen::Vector3d, 2> world;
};
std::vector<TraceSegment> true_trace_segments(const SyntheticScene& scene);

struct SyntheticRender {
  std::array<cv::Mat, 2> images;  // left, right; CV_8UC3
  cv::Mat depth_left;             // CV_32F, metres along the optical axis, 0 = nothing hit
  std::array<photogrammetry::CameraPose, 2> poses;
  photogrammetry::CameraIntrinsics intrinsics;
  std::vector<TargetTruth> targets;  // lower, upper (empty without a range pole)
  std::vector<TraceTruth> traces;
  // The reference line's end points in the left image (distortion included).
  std::optional<std::array<Eigen::Vector2d, 2>> reference_line_left;
};

// Both views and the ground truth. Throws InputError for a scene that cannot
// be rendered (a station looking straight up, a degenerate patch).
SyntheticRender render_scene(const SyntheticScene& scene, Progress& progress);

// Target centres and their normals in world coordinates (lower, upper).
std::vector<TargetTruth> range_pole_targets(const SyntheticScene& scene);

}  // namespace rockface::camera
