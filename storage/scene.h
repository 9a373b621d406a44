#pragma once
// The scene file (SCENE.md, format rockface-scene/1) as plain values. Parsing
// checks what one field can check on its own (types, ranges, known ids,
// duplicates) and throws rockface::InputError naming the file and the field
// path ("tunnel.scene.json: joints[2].dip: 95 is outside [0, 90]").
//
// Angles stay in degrees here, as in the file; points stay absolute. The
// analysis converts to radians and datum-relative coordinates.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/preset.h"
#include "core/measure/picks.h"
#include "core/rockmass/classification_form.h"
#include "storage/scene_tunnel.h"
#include "storage/scene_wedges.h"

namespace rockface::storage {

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

struct SceneImagingCamera {
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  std::array<double, 5> distortion{};
};

struct SceneStation {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d look_at = Eigen::Vector3d::UnitY();
};

struct SceneRangePole {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  double length = 2.0;
  double target_diameter = 0.25;
};

// The face as a tunnel lights it (docs/scene-extensions.md): flash, lamps,
// vignetting, sensor, jpeg_quality, wet, shotcrete, dust.
struct SceneRegion {
  std::string id;
  std::vector<Eigen::Vector3d> polygon;  // absolute, like surface.patches
};
struct SceneLamp {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // absolute
  double intensity = 1.0;                              // full white x m^2
};
struct SceneWet {
  SceneRegion region;
  double specular = 0.5, shininess = 60, darkening = 0.6;
};
struct SceneShotcrete {
  SceneRegion region;
  double albedo = 0.55;
};
struct SceneSensor {
  double iso = 100, base_iso = 100, full_well_e = 40000, read_noise_e = 3.0;
  unsigned seed = 1;
};
struct SceneDust {
  double beta_per_m = 0;  // given, or 3.912 / visibility_m
  double airlight = 0.35;
};

struct SceneImagingEffects {
  bool distortion = false;
  double noise_sigma = 0;  // grey levels
  double blur_px = 0;      // Gaussian sigma, pixels
  double exposure = 1.0;   // gain
  // The face as a tunnel lights it.
  std::optional<double> flash;  // intensity: 1 exposes the look_at distance to full white
  std::vector<SceneLamp> lamps;
  std::optional<double> vignetting;  // strength: 1 = cos^4
  std::optional<SceneSensor> sensor;
  std::optional<int> jpeg_quality;
  std::vector<SceneWet> wet;
  std::vector<SceneShotcrete> shotcrete;
  std::optional<SceneDust> dust;
};

struct SceneImaging {
  SceneImagingCamera camera;
  // Left, right of the first pair, then left, right of each further pair of
  // the same visit (several 3D images of one face; docs/scene-extensions.md).
  std::vector<SceneStation> stations;
  std::optional<SceneRangePole> range_pole;
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> reference_line;
  SceneImagingEffects effects;
  unsigned texture_seed = 7;
};

struct Scene {
  std::string source;  // file the scene came from (for messages)
  std::string name;
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
  std::optional<SceneImaging> imaging;
  // Picks on the reconstructed image (docs/scene-extensions.md): the replay
  // measures its traces from them instead of taking the synthetic truth.
  std::optional<measure::Picks> picks;
  // The tunnel the face lies in (docs/scene-extensions.md, "tunnel").
  std::optional<SceneTunnel> tunnel;
  std::optional<SceneWedges> wedges;  // the wedges around the excavation (issue 23)
  // The rock-mass classification form (docs/scene-extensions.md,
  // "rockmass"): what the geologist entered on site; the replay stores it
  // with the visit.
  std::optional<rockmass::ClassificationForm> rockmass;

  const SceneJoint* joint(const std::string& id) const;
  const SceneFreeFace* free_face(const std::string& id) const;
  // Index of a plane id among joints followed by free faces, -1 if unknown.
  int plane_index(const std::string& id) const;
};

// Reads and validates a scene file. Throws InputError naming the file and field.
Scene load_scene(const std::string& path);
// Parses scene text; `source` names it in messages.
Scene parse_scene(const std::string& text, const std::string& source);

}  // namespace rockface::storage
