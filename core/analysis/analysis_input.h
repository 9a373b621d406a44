#pragma once
// What the block analysis takes, as values (no file formats): the planes
// (joints, then free faces: a block code has one digit per plane in this
// order), the explicit blocks, the free surface and the traces on it, the
// rock, the effects and the analysis options. storage/scene/scene.h reads the
// parts from a scene file (SCENE.md) and firmware-app/analysis/scene_input.h
// makes the whole from it once, at the boundary; the replay fills it with
// the measured joint planes and traces.
//
// Angles stay in degrees here, as in the scene file; points stay absolute.
// The analysis converts to radians and datum-relative coordinates.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/preset.h"
#include "core/rockmass/classification_form.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"

namespace rockface::analysis {

// A joint's cohesion is taken in [0, 100 MPa]: joints' cohesion is rarely
// above 1 MPa and intact rock's below ~50 MPa; 1e308 was taken, and a
// wedge's factor of safety overflowed (issue 41).
inline constexpr double kMaxJointCohesionPa = 1e8;

struct SceneJoint {
  std::string id;
  double dip = 0, dipdir = 0;            // degrees
  std::optional<Eigen::Vector3d> point;  // absolute
  std::optional<double> friction;        // degrees
  std::optional<double> cohesion;        // Pa
};

struct SceneFreeFace {
  std::string id;
  double dip = 0, dipdir = 0;
  std::optional<Eigen::Vector3d> point;
  int rock_side = 0;  // 0 = upper, 1 = lower (half-space code)
  std::string group;  // faces sharing a group form one excavation pyramid
};

struct SceneBlockFace {
  std::string plane;      // a joint or free-face id
  std::vector<int> loop;  // vertex indices, counter-clockwise seen from outside
};

struct SceneBlock {
  std::string id;
  std::map<std::string, int> halfspaces;  // plane id -> code 0 / 1 (halfspaces form)
  std::vector<Eigen::Vector3d> vertices;  // vertices form (absolute)
  std::vector<SceneBlockFace> faces;
  bool has_halfspaces() const { return !halfspaces.empty(); }
};

struct ScenePatch {
  std::string id;
  std::vector<Eigen::Vector3d> polygon;
};

struct SceneTrace {
  std::string id;
  std::optional<std::string> joint;
  std::vector<Eigen::Vector3d> points;
};

struct SceneRemoteAxis {
  std::optional<int> starts;  // none: the preset's (fast 16, standard 64, precise 256)
  unsigned seed = 1;
};

// analysis.dynamics: the block's motion after failure (docs/scene-extensions.md).
struct SceneFloor {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // absolute
  double dip = 0, dipdir = 0;                       // degrees; level by default
};

struct SceneDynamics {
  double duration_s = 2.0;          // s of motion after failure
  double sample_s = 0.2;            // s between the path's samples
  std::optional<SceneFloor> floor;  // where a block in free flight lands
  // Time-step knobs; none: the preset's (docs/scene-extensions.md).
  std::optional<double> abs_tol, rel_tol, max_step_s;
};

struct SceneAnalysis {
  bool pyramids = true;
  bool blocks = true;
  bool rotation = true;
  std::optional<SceneRemoteAxis> remote_axis;
  std::string stability = "limit_equilibrium";  // or "equilibrium_path"
  Preset preset = Preset::standard;             // analysis.preset; missing: standard
  // Added fields (documented in docs/scene-extensions.md):
  double orientation_uncertainty_deg = 1.0;  // verdicts inside it are marginal
  std::optional<double> reference_mass;      // kg, scales `forces` for pyramids
  double snap_tolerance = 0.05;              // m, trace snapping
  // m: how well the planes' points are known. Four or more planes of a
  // block that pass within it of one corner are taken through one point
  // (blocks::build_convex_block); the default, a micrometre, is the
  // rounding of coordinates written to six decimals.
  double survey_precision_m = 1e-6;
  // Equilibrium path (stability "equilibrium_path"); none: the preset's.
  std::optional<int> contact_density;       // sub-divisions per triangle edge
  std::optional<double> continuation_step;  // initial arc-length step (lambda units)
  std::optional<int> max_steps;             // continuation steps before "no limit point"
  std::optional<double> lambda_max;         // largest load factor tried
  // The block's motion after failure; none: not simulated.
  std::optional<SceneDynamics> dynamics;
};

struct SceneWater {
  double unit_weight = 9810;  // N/m^3
  Eigen::Vector3d phreatic_point = Eigen::Vector3d::Zero();
  double phreatic_dip = 0, phreatic_dipdir = 0;  // degrees
  std::vector<std::string> joints;               // empty: all joints
};

struct SceneForce {
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();  // N
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // absolute
  std::string frame = "space";                       // "space" or "block" (follower)
};

struct SceneBolt {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double trend = 0, plunge = 0;  // degrees; pulls the block along it
  double force = 0;              // N
};

struct SceneJointLaw {
  std::string model = "barton_bandis";  // barton_bandis | grasselli | coulomb
  double jrc = 10, jcs = 1e8, phi_b = 30;
  // Added fields (docs/scene-extensions.md):
  double normal_stiffness = 1e10;      // Pa/m
  double poisson_ratio = 0.25;         // shear stiffness = kn / (2 (1 + nu))
  std::optional<double> phi_r;         // degrees; default phi_b
  double lab_length = 0.1;             // m, L0 of JRC and JCS
  std::optional<double> field_length;  // m, Ln: scale corrections when given
  bool dilation = true;
};

struct SceneEffects {
  std::optional<SceneWater> water;
  std::optional<Eigen::Vector3d> seismic;        // m/s^2, pseudo-static
  std::optional<Eigen::Matrix3d> insitu_stress;  // Pa, compression positive
  std::vector<SceneForce> forces;
  std::vector<SceneBolt> bolts;
  std::optional<SceneJointLaw> joint_law;
  // Names in the fixed order of SCENE.md, "gravity" first: what the scene asks for.
  std::vector<std::string> listed() const;
};

struct AnalysisInput {
  std::string source;  // names the input in messages (a scene file, a project's visit)
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  bool has_datum = false;
  double density = 2700;  // kg/m^3
  Eigen::Vector3d gravity{0, 0, -9.81};
  std::vector<SceneJoint> joints;
  std::vector<SceneFreeFace> free_faces;
  std::vector<SceneBlock> blocks;
  std::vector<ScenePatch> patches;
  std::vector<SceneTrace> traces;
  SceneAnalysis analysis;
  SceneEffects effects;
  // The rock-mass form the scene brings (its `rockmass` section), for the
  // report's rock-mass section.
  std::optional<rockmass::ClassificationForm> rockmass_form;

  const SceneJoint* joint(const std::string& id) const;
  // Index of a plane id among joints followed by free faces, -1 if unknown.
  int plane_index(const std::string& id) const;
};

// The invert of a tunnel at the face's chainage as the floor a falling block
// lands on (analysis.dynamics without a floor): the design profile's lowest
// point, in the plane of the cross-section's right and the drive. `alignment`
// is built with `datum`; the floor's point is absolute.
SceneFloor tunnel_invert_floor(const tunnel::Alignment& alignment,
                               const tunnel::DesignProfile& profile, double chainage,
                               const Eigen::Vector3d& datum);

}  // namespace rockface::analysis
