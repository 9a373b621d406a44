#pragma once
// The mapped face as a sampling window. A geologist's scanlines and window
// counts lie on the face: its plane (fitted to the mapped outline), two
// in-face axes (h horizontal along the face, v up the face), its outline
// (the convex hull of what was mapped, in (h, v) metres) and its area.
// Traces are drawn on it as 2D polylines.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rockface::rockmass {

// One trace of the visit as the rock-mass figures take it.
struct FaceTrace {
  std::string label;                    // "T3"
  std::vector<Eigen::Vector3d> points;  // project frame, along the trace
  // Its own plane's normal where its points give one (not straight).
  std::optional<Eigen::Vector3d> normal;
  // Its joint ("J7"): the pieces of one joint traced apart are one
  // discontinuity in the spacing. Empty when unassigned.
  std::string joint_label;
  std::string set_label;  // the set its joint belongs to, when stored so
  std::optional<double> length_m;
  bool censored = false;  // an end leaves the mapped area
};

struct FaceWindow {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // unit, out of the face or into it
  Eigen::Vector3d h = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitZ();  // unit, in-face
  std::vector<Eigen::Vector2d> outline;  // convex, counter-clockwise in (h, v)
  double area_m2 = 0;

  Eigen::Vector2d to_face(const Eigen::Vector3d& p) const;
  Eigen::Vector3d to_space(const Eigen::Vector2d& q) const;
  // The in-face direction at `angle_deg` from h towards v, in space.
  Eigen::Vector3d direction(double angle_deg) const;
};

// The window of the mapped face: plane and outline from `outline_points`
// (the mapped traces' points: the window is where joints were mapped). Throws InputError("face",
// ...) when fewer than three points or all on a line.
FaceWindow face_window(const std::vector<Eigen::Vector3d>& outline_points);

}  // namespace rockface::rockmass
