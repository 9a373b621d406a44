#pragma once
// The records a project file holds: plain values that the field workflow
// produces (camera, photogrammetry, measure, blocks) and ProjectStore saves and
// loads. They are deliberately simple and stable: other parts convert their own
// types to these at the boundary, so that a change inside an algorithm does not
// change what is on a geologist's card.
//
// Coordinates are in the project frame of DESIGN.md (x = East, y = North,
// z = Up, metres) and relative to the project's datum; exports add the datum
// back. Angles are degrees (dip in [0, 90], dip direction in [0, 360)).
// Time stamps are UTC ISO 8601 text ("2026-11-21T05:20:11.123Z").
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/report.h"
#include "core/photogrammetry/camera/camera_model.h"
#include "core/photogrammetry/estimators/registration.h"

namespace rockface::storage {

// Row id of a record in its table; ids are never reused within a project.
using RecordId = std::int64_t;

struct ProjectInfo {
  std::string name;
  // Site origin in survey coordinates; every stored point is relative to it.
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  std::string datum_crs;   // free text, e.g. "EPSG:2056 LV95 / LN02"; may be empty
  std::string created_at;  // set by the store when the project is created
  std::string created_by;  // program and version that created the file
};

// One stay at the face (a day, or one run of `rockface replay`). Every record
// below that comes from the field belongs to a visit.
struct Visit {
  RecordId id = 0;
  std::string started_at;
  std::string source;  // what started it: "tablet", "replay DIR", ...
  std::string note;
  // The geologist who mapped it (schema 13, storage/project/visit_geologist.h);
  // none for a visit of an older project or one nobody named.
  std::optional<std::string> geologist;
};

struct CameraBody {
  RecordId id = 0;
  std::string make, model, serial;  // (make, model, serial) identifies a body
};

struct Calibration {
  RecordId id = 0;
  std::optional<RecordId> body_id;
  // fx, fy, cx, cy, k1 k2 p1 p2 k3, width, height, rms and the provenance
  // strings (body, lens, focus) exactly as the calibration produced them.
  photogrammetry::CameraIntrinsics intrinsics;
  double focal_setting_mm = 0;  // the zoom setting the lens was taped at; 0 if unknown
  std::string method;           // e.g. "chessboard:9x6:0.025", "synthetic"
  std::string created_at;       // set by the store when empty
};

// Encoded image bytes exactly as the camera delivered them (JPEG or PNG).
struct ImageBlob {
  std::vector<std::uint8_t> bytes;
  std::string format;  // "jpeg" | "png": detected by the store from the bytes
};

// A stereo pair and everything known about how it was taken.
struct Capture {
  RecordId id = 0;
  RecordId visit_id = 0;
  std::optional<RecordId> calibration_id;
  std::string label;     // e.g. "face 120 left-right"
  std::string taken_at;  // from EXIF or the camera clock; set by the store when empty
  ImageBlob left, right;
  std::map<std::string, std::string> settings;  // camera settings: iso, shutter, aperture, ...
  std::map<std::string, std::string> left_exif, right_exif;
};

// A capture without its image bytes, for lists.
struct CaptureSummary {
  RecordId id = 0;
  RecordId visit_id = 0;
  std::optional<RecordId> calibration_id;
  std::string label, taken_at;
  std::string left_format, right_format;
  std::int64_t left_bytes = 0, right_bytes = 0;
};

// A triangle mesh in project coordinates. texcoords and colours are either
// empty or one per vertex; texcoords are normalised image coordinates (u to
// the right, v down, both in [0, 1]) in the texture image.
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::int32_t, 3>> faces;
  std::vector<std::array<float, 2>> texcoords;
  std::vector<std::array<std::uint8_t, 3>> colours;  // RGB
};

// What ties the reconstructed (model) frame to the project frame:
// x_project = scale * rotation * x_model + translation.
struct Registration {
  std::string kind;  // "range_pole_compass" | "ground_control" | "none"
  double scale = 1;
  Eigen::Vector4d rotation_wxyz{1, 0, 0, 0};  // unit quaternion
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  std::string parameters_json;  // inputs of that kind (pole length, azimuth, GCP file, ...)
  double rms_m = 0;
};

// Misfit of one control item (a pole target, a ground control point) after
// registration, in metres, project frame.
struct RegistrationResidual {
  std::string label;
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();
};

struct Model {
  RecordId id = 0;
  std::optional<RecordId> capture_id;  // the pair it was reconstructed from
  std::string preset;                  // fast | standard | precise
  std::string created_at;
  Mesh mesh;
  // The texture is an image of a stored capture, not a copy of it.
  std::optional<RecordId> texture_capture_id;
  std::string texture_side;  // "left" | "right" when texture_capture_id is set
  Registration registration;
  std::vector<RegistrationResidual> residuals;
  // The map from the reconstruction's camera frame (the left camera's, of
  // core/photogrammetry/estimators/relative_orientation.h) to the frame of `mesh`: what
  // a view of the model's photographs needs (measure::left_view). A model
  // registered on its own (range pole, control points, none) has its
  // registration here, and save_model takes that when this is not given. A
  // further pair of a visit (registration kind "face_images", whose
  // registration is its 3D image's map onto the face) has its camera's map
  // followed by that one. Nothing for a further pair stored before schema 4.
  std::optional<photogrammetry::Similarity> camera_to_mesh;
};

// The similarity a registration record holds (x_mesh = scale R x + t), and
// the record's scale, rotation and translation of one.
photogrammetry::Similarity similarity_of(const Registration& r);
void set_similarity(Registration& r, const photogrammetry::Similarity& s);

struct ModelSummary {
  RecordId id = 0;
  std::optional<RecordId> capture_id;
  std::string preset, created_at, registration_kind;
  std::int64_t vertex_count = 0, face_count = 0;
  double registration_rms_m = 0;
};

// Something measured on a model: a joint trace (polyline), an area (a patch of
// the free surface, polygon), or a point orientation (one point and the plane
// measured there).
struct Measurement {
  enum class Kind { trace, area, point_orientation };
  RecordId id = 0;
  RecordId visit_id = 0;
  std::optional<RecordId> model_id;
  Kind kind = Kind::trace;
  std::string label;        // "T1", "S1", ...
  std::string joint_label;  // trace: the joint it belongs to, empty when unassigned
  std::vector<Eigen::Vector3d> points;
  // The plane fitted to (or measured at) the points; absent for a trace that
  // could not be fitted (collinear).
  std::optional<double> dip_deg, dipdir_deg;
  double fit_rms_m = 0;
  // area only: when the area is a free face of the excavation, where the rock
  // lies relative to its plane ("upper" or "lower", SCENE.md); empty otherwise.
  std::string rock_side;
  std::string created_at;
  // Where it was measured, so that it can be shown again: the photograph
  // ("left" | "right" of capture photo_capture_id, or a view name) and the
  // pixels picked in it (the taps, or the traced path); empty when the
  // points were given, not picked.
  std::string photo;
  std::optional<RecordId> photo_capture_id;
  std::vector<Eigen::Vector2d> pixels;
  std::optional<double> sigma_deg;       // one sigma of the plane's normal, when fitted
  std::optional<double> trace_length_m;  // trace: length along its points
  bool censored = false;  // trace: an end leaves the mapped area (the length is a lower bound)
  std::string note;       // why the orientation is unknown, or a warning about the fit
  // trace: where it came from (issue 25): "hand" (tapped), "proposed" (a
  // trace proposal accepted as found) or "corrected" (a proposal redrawn by
  // least-cost tracing between its dragged ends). Areas and points: "hand".
  std::string origin = "hand";
  // trace (issue 27, schema 9): a compass reading of its joint, degrees, when
  // its plane (dip_deg / dipdir_deg) is that reading; compass_off_deg: the
  // larger angle by which the trace (its line, its fitted plane) leaves the
  // plane read (core/measure/compass_reading.h; the note says it in words).
  std::optional<double> compass_dip_deg, compass_dipdir_deg, compass_off_deg;
};

struct JointSet {
  RecordId id = 0;
  std::string label;  // "S1"
  double dip_deg = 0, dipdir_deg = 0;
  double fisher_k = 0;  // Fisher concentration, 0 if not computed
  int count = 0;
  std::optional<double> alpha95_deg;  // 95 % cone of confidence of the mean pole
  std::optional<double> spacing_m;    // mean spacing normal to the set
  std::optional<double> mean_trace_length_m;
  int censored_traces = 0;              // traces leaving the mapped area
  std::optional<double> persistence_m;  // where it can be estimated
  std::string note;                     // the censoring stated in words
};

struct Joint {
  RecordId id = 0;
  RecordId visit_id = 0;
  std::string label;      // "J1": the id used in scenes and reports
  std::string set_label;  // label of a JointSet saved with it; empty when unassigned
  double dip_deg = 0, dipdir_deg = 0;
  std::optional<Eigen::Vector3d> point;  // a point on the plane (project frame)
  std::optional<double> friction_deg, cohesion_pa;
  std::optional<RecordId> measurement_id;  // the trace or point it was fitted from
  std::string source;                      // "trace T3", "manual", "scene"
  // What was measured (the "type" column of Dips): "trace", "area", "point"
  // or empty (given, not measured).
  std::string type;
  std::optional<double> persistence_m;  // its trace length, when measured
};

// One run of the block analysis: what it was asked to simulate and what it
// found. Each block is the one verdict type (core/analysis/report.h), points
// absolute as in the report; the store keeps it as a row of key columns and
// the block's report JSON (project_block_row.h).
struct AnalysisRun {
  RecordId id = 0;
  RecordId visit_id = 0;
  std::optional<RecordId> model_id;
  std::string preset;                // fast | standard | precise
  std::vector<std::string> effects;  // report "effects_simulated", e.g. gravity, water
  std::string effects_json;          // the scene's "effects" object verbatim, may be empty
  std::string created_at;
  std::vector<analysis::ReportBlock> blocks;
};

struct ActionLogEntry {
  RecordId id = 0;
  std::string at;
  std::optional<RecordId> visit_id;
  std::string action;  // "capture saved", "export ply", ...
  std::string detail;
};

// What PRAGMA integrity_check / quick_check said.
struct IntegrityReport {
  bool ok = false;
  std::vector<std::string> problems;  // empty when ok
};

}  // namespace rockface::storage
