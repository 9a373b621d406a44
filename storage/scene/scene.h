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

#include "core/analysis/analysis_input.h"
#include "core/analysis/wedges_input.h"
#include "core/measure/picks.h"
#include "core/rockmass/classification_form.h"
#include "storage/scene/scene_tunnel.h"

namespace rockface::storage {

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

// A monitoring target of the tunnel's survey (docs/scene-extensions.md):
// drawn as the pole's targets are, its centre's survey coordinates known;
// three or more register the visit (ground control) instead of the pole
// and the compass line.
struct SceneControlTarget {
  std::string id;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double diameter = 0.15;  // m, the black disk; the white one is half of it
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
  std::vector<SceneControlTarget> control_targets;  // none, or three or more
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
  std::vector<analysis::SceneJoint> joints;
  std::vector<analysis::SceneFreeFace> free_faces;
  std::vector<analysis::SceneBlock> blocks;
  std::vector<analysis::ScenePatch> patches;
  std::vector<analysis::SceneTrace> traces;
  analysis::SceneAnalysis analysis;
  analysis::SceneEffects effects;
  std::optional<SceneImaging> imaging;
  // Picks on the reconstructed image (docs/scene-extensions.md): the replay
  // measures its traces from them instead of taking the synthetic truth.
  std::optional<measure::Picks> picks;
  // The tunnel the face lies in (docs/scene-extensions.md, "tunnel").
  std::optional<SceneTunnel> tunnel;
  std::optional<analysis::SceneWedges> wedges;  // the wedges around the excavation (issue 23)
  // The rock-mass classification form (docs/scene-extensions.md,
  // "rockmass"): what the geologist entered on site; the replay stores it
  // with the visit.
  std::optional<rockmass::ClassificationForm> rockmass;

  const analysis::SceneJoint* joint(const std::string& id) const;
  const analysis::SceneFreeFace* free_face(const std::string& id) const;
  // Index of a plane id among joints followed by free faces, -1 if unknown.
  int plane_index(const std::string& id) const;
};

// Reads and validates a scene file. Throws InputError naming the file and field.
Scene load_scene(const std::string& path);
// Parses scene text; `source` names it in messages.
Scene parse_scene(const std::string& text, const std::string& source);

}  // namespace rockface::storage
