#pragma once
// What a stored model's registration says, read once (issue 37: six screens,
// the field report and the placement each parsed the stored parameters
// themselves) and told honestly (issue 42: a model scaled by the range pole
// was recorded as "range pole and compass" whether or not it had a north).
//
// The parameters are the reconstruction's report (rockface-reconstruction/1)
// for a pair's model, or the face registration (rockface-face-registration/1)
// for a further pair placed onto pair 1. A figure the record does not hold is
// absent, never 0: older projects and minimal records hold fewer.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "storage/project/project_records.h"

namespace rockface::storage {

// A range-pole target as detected in the left photograph.
struct RegisteredPoleTarget {
  std::string which;  // "lower" | "upper"
  Eigen::Vector2d left_px = Eigen::Vector2d::Zero();
  std::optional<double> diameter_px;
};

struct RegisteredControlPoint {
  std::string id;
  double distance_m = 0;  // its misfit after registration
};

// One 3D image of a face registration (a further pair onto pair 1).
struct RegisteredImage {
  std::string name, role;  // role: "master" | "registered"
  std::string reference;
  std::optional<double> tie_points, tie_point_rms_m, overlap, surface_rms_m;
  double scale = 1;
};

struct ModelRegistration {
  enum class Record { none, reconstruction, face_images };
  Record record = Record::none;  // which report the parameters hold
  std::string kind;              // as stored, made honest (honest_registration_kind)

  // What scaled, levelled and oriented the model, in the reconstruction's
  // words ("range pole", "control points", "baseline", "compass",
  // "levelled camera", "none"); empty when the record does not say.
  std::string scale_source, vertical_source, north_source;
  std::optional<bool> scaled;
  std::optional<double> scale;

  bool has_format = false;              // the parameters name their format (a report, not a stub)
  bool has_pole = false;                // the range pole scaled it (its length and targets follow)
  std::optional<double> pole_length_m;  // as recorded (0 when no length was given)
  std::vector<RegisteredPoleTarget> pole_targets;
  std::vector<Eigen::Vector3d> targets_project;  // the pole's targets, project frame

  bool has_north = false;  // the record holds a compass line
  std::optional<double> compass_azimuth_deg, declination_deg, north_rotation_deg;

  std::optional<double> predicted_depth_sigma_mm, sigma_z_m, distance_m, base_m, base_to_distance,
      point_spacing_m;
  std::optional<double> inliers, matches, rms_reprojection_px, tie_point_coverage;
  std::optional<double> dense_valid_fraction, dense_image_scale;

  bool has_control_points = false;
  std::optional<double> control_rms_m, worst_control_m;
  std::string worst_control;
  std::vector<RegisteredControlPoint> control_points;

  std::vector<RegisteredImage> images;  // face registration only

  // A 3D image imported from another program (`rockface import`, format
  // rockface-import/1): where it came from, in words ("scan.las: LAS 1.4
  // point format 7, 120000 points, survey coordinates"); empty otherwise.
  std::string imported_from;
  std::vector<std::string> warnings;

  // North is known: from a compass line or control points, or (a further
  // pair) from pair 1. False for a model nothing oriented.
  bool oriented() const;
  // Lengths are in metres: false for a model nothing scaled (in units of
  // the camera base).
  bool is_scaled() const { return kind != "none" && scaled.value_or(true); }
};

// Reads the stored registration; malformed or missing parameters give a
// record with only the kind (never throws: a screen shows what there is).
ModelRegistration read_model_registration(const Registration& r);

// The registration kind of a 3D image imported in survey coordinates: the
// scanner's (or the drone software's) registration scaled, levelled and
// oriented it; rockface did not.
inline constexpr const char* kScannerRegistration = "scanner";
inline constexpr const char* kScannerRegistrationWords = "the scanner's registration";

// The kind a model's registration is recorded under, from what the
// reconstruction used: "range_pole_compass", "range_pole" (scaled and
// levelled by the pole, no north), "ground_control", "baseline", "none".
std::string registration_kind(const std::string& scale_source, const std::string& north_source);

// A stored kind made honest: projects written before issue 42 recorded every
// pole-scaled model as "range_pole_compass" and control points as "control
// points"; `north_source` is what the stored report says (empty if nothing).
std::string honest_registration_kind(const std::string& stored_kind,
                                     const std::string& north_source);

}  // namespace rockface::storage
