#pragma once
// Registration: from the model frame of the relative orientation (left
// camera, base = 1) to the scene frame (x = East, y = North, z = Up, metres)
// by a similarity transform x_world = scale * R x_model + t. The sources:
// a vertical range pole with two targets (scale + vertical), the compass
// azimuth of a reference line (north), ground control points (everything),
// and a measured base length (scale).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rockface::photogrammetry {

struct Similarity {
  double scale = 1;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& x) const { return scale * (R * x) + t; }
  // This transform followed by `next`.
  Similarity then(const Similarity& next) const {
    return {next.scale * scale, next.R * R, next.scale * (next.R * t) + next.t};
  }
};

// Without any vertical source: the left camera is taken as level and without
// roll (a tripod; SCENE.md stations), so camera x -> East-ish, the optical
// axis -> North-ish, camera -y -> Up. Heading and tilt are then only as good
// as the photographer's levelling; the report says so.
Similarity levelled_camera_frame();

// Range pole: `lower` and `upper` target centres in the model frame. Scales
// so that their distance is `length_m`, rotates the pole onto +z (vertical),
// keeps the left camera's optical axis pointing north (heading arbitrary until
// a north source is applied) and puts the lower target at the origin.
// Throws InputError when the targets coincide or the pole is not upward-ish.
Similarity range_pole_registration(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper,
                                   double length_m);

// Scale only, from the measured distance between the two camera stations;
// model base is `model_base` (1 after relative orientation).
Similarity baseline_scale(double base_m, double model_base = 1.0);

// Horizontal bearing of the line from -> to, degrees clockwise from +y
// (north), in [0, 360). Throws InputError when the line is (nearly) vertical.
double horizontal_azimuth_deg(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

// North: rotation about the vertical through `pivot` that turns the line
// from -> to (world frame, already vertical) to the true azimuth
// compass_deg + declination_deg (declination east positive).
Similarity north_rotation(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                          double compass_deg, double declination_deg,
                          const Eigen::Vector3d& pivot = Eigen::Vector3d::Zero());

struct ControlPoint {
  std::string id;
  Eigen::Vector2d pixel;  // in the left image
  Eigen::Vector3d world;  // scene frame, absolute (survey) coordinates
};

struct ControlPointResidual {
  std::string id;
  Eigen::Vector3d residual;  // transformed model point - surveyed point, metres
  double distance = 0;       // its length
  // Measured on its circular target in both photographs (control_targets.h),
  // else read from the 3D image at the pick.
  bool on_target = false;
};

struct ControlPointRegistration {
  Similarity transform;   // model -> datum-relative world
  Eigen::Vector3d datum;  // absolute = datum-relative + datum
  std::vector<ControlPointResidual> residuals;
  double rms_m = 0;
  std::string worst_id;
  double worst_m = 0;
};

// Umeyama similarity between the model points and the surveyed points of
// three or more control points (not collinear). Computed relative to the
// centroid of the survey coordinates (the datum), so 10^6 m survey
// coordinates lose no precision.
ControlPointRegistration register_to_control_points(const std::vector<Eigen::Vector3d>& model,
                                                    const std::vector<ControlPoint>& points,
                                                    const std::string& where);

// Parses a control-point CSV: one point a line, `id,u,v,X,Y,Z`; an optional
// header line and '#' comments. Throws InputError naming `where` and the line.
// "4 of 5 measured on their targets, rms 3.1 mm, worst T2 (5.0 mm)": how
// the registration's points were read and how well they agree.
std::string control_points_summary(const ControlPointRegistration& r);

std::vector<ControlPoint> parse_control_points(std::istream& in, const std::string& where);

}  // namespace rockface::photogrammetry
