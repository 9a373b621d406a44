#pragma once
// The analysis report as plain values: the one report and the one block
// verdict (ReportBlock) that the command line, the tablet, the field report,
// the office sync and the tests all read. The analysis (scene_analysis.h)
// fills it; storage/report/report.h writes it as rockface-report/1 (SCENE.md).
// Coordinates here are absolute (datum added back); angles in degrees.
// Optional parts are written only when present, so a report holds exactly
// what was analysed.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/rockmass/rock_mass_figures.h"

namespace rockface::analysis {

struct ReportMode {
  std::string type = "none";        // falling | lifting | sliding | none
  std::vector<std::string> planes;  // plane ids of the sliding planes
  std::optional<Eigen::Vector3d> direction;
  bool marginal = false;  // the resultant lies within tolerance of a mode boundary
};

struct ReportPyramid {
  std::string face;  // free face id, or the group name of several faces
  std::string code;  // one digit per joint, scene order
  bool empty = false, finite = false, removable = false;
  double margin_deg = 0;  // of the removability verdict
  bool marginal = false;
  double jp_margin_deg = 0;        // signed: JP open (> 0) or shut (< 0)
  double jp_ep_margin_deg = 0;     // signed: JP cap EP open (> 0) or shut (< 0)
  std::optional<ReportMode> mode;  // removable pyramids only
  std::optional<double> fos;       // friction only; absent when no strengths or no sliding
};

struct ReportCorner {
  int vertex = 0;
  bool rotatable = false;
  double margin_deg = 0;
  bool marginal = false;
  std::vector<Eigen::Vector3d> rotation_edges;  // extreme rays of the rotation space
  std::vector<std::string> sliding_on;          // joints the block slides on while rotating
};

struct ReportEdge {
  std::array<int, 2> vertices{};
  bool rotatable = false;
  double margin_deg = 0;
  bool marginal = false;
};

struct ReportRotation {
  std::vector<ReportCorner> corners;
  std::vector<ReportEdge> edges;
};

struct ReportRemoteAxis {
  bool found = false;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  int starts = 0, hits = 0;
  double penalty = 0;  // best objective reached
};

struct ReportStabilityStep {
  double lambda = 0;
  std::vector<double> displacement;
};

struct ReportStability {
  std::optional<double> fos;
  std::vector<double> static_mode, dynamic_mode;
  std::vector<ReportStabilityStep> path;
};

// The equilibrium-path analysis of one block (analysis.stability =
// "equilibrium_path"; docs/scene-extensions.md, "Report additions").
struct ReportRigidMode {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // of the centroid
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();     // rad, rotation vector
  std::string kind = "translation";                       // "translation" | "rotation"
};

struct ReportMechanics {
  std::optional<double> fos_limit_point;    // lambda at the first limit point
  std::string outcome;                      // "limit point", "no limit point reached", ...
  ReportRigidMode failure_mode;             // static: null vector of the tangent stiffness
  ReportRigidMode dynamic_mode;             // from M z'' + K z = 0
  std::string stability;                    // "divergence" | "flutter" | "stable"
  std::optional<double> flutter_lambda;     // first lambda with a complex eigenpair
  std::vector<std::array<double, 2>> path;  // [lambda, largest vertex displacement (m)]
  int contacts = 0, steps = 0;
  std::string joint_law;            // model name
  std::optional<std::string> plot;  // PNG of the path, beside the report
};

// The block's motion after failure (analysis.dynamics; docs/scene-extensions.md
// "Dynamics after failure"). Points absolute, times in s, energies in J.
struct ReportMotionEvent {
  double time_s = 0;
  std::string kind;                 // slides | rotates | leaves | free_fall | hits | lands | rest
  std::string what;                 // "leaves J1", "rotates about edge J2-J3"
  std::vector<std::string> planes;  // the planes it names
};

struct ReportMotionSample {
  double time_s = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centroid, absolute
  Eigen::Vector4d orientation{1, 0, 0, 0};             // unit quaternion (w, x, y, z) from rest
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, global axes
  double kinetic_translational = 0, kinetic_rotational = 0;    // J
  double work = 0;        // J, of gravity and the effects since rest
  double dissipated = 0;  // J, work - kinetic energy (friction, impacts)
};

struct ReportLanding {
  double time_s = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();           // first corner on the floor, absolute
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();        // absolute
  double speed = 0, corner_speed = 0, angular_speed = 0;     // m/s, m/s, rad/s
  double kinetic_translational = 0, kinetic_rotational = 0;  // J
  double distance_from_start = 0;                            // m, horizontal
  std::optional<double> distance_from_face;                  // m, horizontal, in front of `face`
  std::string face;
};

struct ReportDynamics {
  std::string trigger;          // why it ran: "limit equilibrium: FoS 0.72 < 1", ...
  std::string outcome;          // "lands", "at rest", "moving at the end", ...
  std::string stopped;          // why the integration stopped before its end (its budget), or empty
  double strength_divisor = 1;  // friction tan / this (the limit point's lambda)
  std::map<std::string, double> friction_deg;  // per joint, while sliding; cohesion lost
  std::vector<ReportMotionEvent> events;
  std::vector<ReportMotionSample> path;
  std::optional<ReportLanding> landing;
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>>
      floor;  // point (absolute), unit up normal
  double duration_s = 0, sample_s = 0, end_time_s = 0;
  double abs_tol = 0, rel_tol = 0, max_step_s = 0;
  int steps = 0, rejected_steps = 0, evaluations = 0;
  double drift_before_m = 0, drift_after_m = 0, drift_bound_m = 0;
  std::optional<std::string> picture;  // PNG beside the report
  std::vector<std::string> notes;
};

struct ReportBlock {
  std::string id;
  std::string source = "scene";     // "scene" or "traces"
  std::vector<std::string> traces;  // trace ids of the loop (source "traces")
  std::string code;
  bool convex = true;
  std::vector<Eigen::Vector3d> vertices;
  // The block's faces as loops of indices into `vertices`, counter-clockwise
  // seen from outside: what a closed mesh of the block needs (the DXF
  // export, the browser). Empty when the vertices are the block's loop on
  // the free surface, and for blocks stored before faces were reported.
  std::vector<std::vector<int>> faces;
  std::optional<double> volume, mass;
  std::optional<Eigen::Vector3d> centroid;
  std::optional<Eigen::Matrix3d> inertia;
  std::optional<Eigen::Vector3d> principal_moments;
  std::map<std::string, double> face_areas;
  bool finite = false, removable = false;
  double margin_deg = 0;
  bool marginal = false;
  std::optional<ReportMode> mode;
  std::optional<double> fos;
  // The FoS lies within its own tolerance of 1 (block_report.cpp): whether
  // the block fails is not decided by the data; a note says why.
  bool fos_marginal = false;
  // Active resultant of gravity and the scene's effects (N), and its moment
  // about the centroid (N m): what a toppling or rotation check starts from;
  // the limit equilibrium above is translational.
  std::optional<Eigen::Vector3d> resultant_force, resultant_moment;
  std::optional<ReportRotation> rotation;
  std::optional<ReportRemoteAxis> remote_axis;
  std::optional<ReportStability> stability;
  std::optional<ReportMechanics> mechanics;
  std::optional<ReportDynamics> dynamics;  // analysis.dynamics, failing blocks only
  std::vector<std::string> notes;          // e.g. "face J3 opens under water pressure"
};

struct Report {
  std::vector<std::string> effects_simulated{"gravity"};
  // The analyses that ran: "geometry" always, then "limit_equilibrium" or
  // "equilibrium_path" (with its own "mechanics" per block).
  std::vector<std::string> analyses{"geometry"};
  std::vector<ReportPyramid> pyramids;
  std::vector<ReportBlock> blocks;
  std::vector<std::string> notes;  // scene-level notes (traces left out, effects not applicable)
  std::map<std::string, double> timings_ms;
  // The rock mass in figures of the trace map (core/rockmass); none when the
  // analysis had no traces or they make no face window (see
  // docs/scene-extensions.md, "The rock mass in figures").
  std::optional<rockmass::RockMassFigures> rockmass;
};

// A readable table for a terminal: one line per removable or marginal
// pyramid and per block, with verdicts, margins, modes and factors of safety.
std::string report_summary(const Report& report);
// One event of a block's motion in words: "leaves J1 at 0.34 s".
std::string event_text(const ReportMotionEvent& e);

}  // namespace rockface::analysis
