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

// A monitoring target of the tunnel's survey: drawn as the pole's targets
// are (a black disk, a white one of half its diameter at its centre, facing
// the stations' midpoint as a surveyor turns a target to the instrument).
struct SyntheticControlTarget {
  std::string id;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double diameter = 0.15;  // m
};

// Tunnel lighting and imaging (docs/scene-extensions.md, "The face as a
// tunnel lights it"). Each is off unless the scene asks for it.

// A flash at each station's camera: a point light whose irradiance falls
// with the distance squared and the cosine of the angle of incidence. At
// `intensity` 1 a face-on surface at the station's look_at distance gets
// the full white of the default lighting (a TTL flash exposes for the
// focus point).
struct SyntheticFlash {
  double intensity = 1.0;
};

// A lamp (the jumbo's work lights): a point light at `position`; a surface
// facing it at distance d gets intensity / d^2 of full white.
struct SyntheticLamp {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double intensity = 1.0;  // full white x m^2
};

// A region on the face: points of the surface within kRegionReach of the
// polygon's plane whose projection on it falls inside the polygon.
struct SyntheticRegion {
  std::string id;
  std::vector<Eigen::Vector3d> polygon;        // at least 3 points, planar
  static constexpr double kRegionReach = 0.3;  // m: a face is not flatter than this
};

// Water on the rock: darker albedo and a specular (Blinn-Phong) lobe.
struct SyntheticWet {
  SyntheticRegion region;
  double specular = 0.5;   // k_s: peak reflectance of the lobe, of full white
  double shininess = 60;   // Blinn-Phong exponent
  double darkening = 0.6;  // albedo factor of wet rock
};

// Sprayed concrete: grey, smooth, no texture and no joint traces.
struct SyntheticShotcrete {
  SyntheticRegion region;
  double albedo = 0.55;
};

// The sensor at an ISO: shot noise (Poisson, sqrt of the electrons) and
// read noise, in electrons; full scale (255) holds full_well_e * base_iso
// / iso electrons.
struct SyntheticSensor {
  double iso = 100;
  double base_iso = 100;
  double full_well_e = 40000;  // electrons at base ISO (APS-C DSLR, ~4 um pixels)
  double read_noise_e = 3.0;   // electrons rms
  unsigned seed = 1;
};

// Dust in the air (Koschmieder): radiance attenuated by exp(-beta d) toward
// the airlight over the distance d from the camera.
struct SyntheticDust {
  double beta_per_m = 0;   // extinction coefficient; visibility = 3.912 / beta
  double airlight = 0.35;  // grey of the lit haze, of full white
};

// Imaging effects; each is off unless the scene switches it on.
struct SyntheticEffects {
  bool distortion = false;  // render through the camera's Brown distortion
  double noise_sigma = 0;   // Gaussian sensor noise, grey levels (0..255)
  double blur_px = 0;       // Gaussian blur sigma, pixels
  double exposure = 1.0;    // gain on the rendered radiance
  // The face as a tunnel lights it.
  std::optional<SyntheticFlash> flash;
  std::vector<SyntheticLamp> lamps;
  std::optional<double> vignetting;  // strength: 1 = the cos^4 law of a simple lens
  std::optional<SyntheticSensor> sensor;
  std::optional<int> jpeg_quality;  // 1..100: a JPEG round trip at this quality
  std::vector<SyntheticWet> wet;
  std::vector<SyntheticShotcrete> shotcrete;
  std::optional<SyntheticDust> dust;
  // What ran, by the scene's field names, in a fixed order (distortion,
  // noise_sigma, blur_px, exposure, flash, lamps, vignetting, sensor,
  // jpeg_quality, wet, shotcrete, dust).
  std::vector<std::string> simulated() const;
  bool tunnel_lit() const { return flash.has_value() || !lamps.empty(); }
};

struct SyntheticScene {
  std::vector<SyntheticPatch> patches;
  std::vector<SyntheticJoint> joints;        // only joints with a point
  photogrammetry::CameraIntrinsics camera;   // distortion used only with effects.distortion
  std::array<SyntheticStation, 2> stations;  // left, right
  std::optional<SyntheticRangePole> range_pole;
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> reference_line;  // from, to
  std::vector<SyntheticControlTarget> control_targets;
  SyntheticEffects effects;
  unsigned texture_seed = 7;
};

// World-to-camera pose of a station (OpenCV axes: z forward, x right, y
// down). Throws InputError naming `where` when the station looks straight
// up or down (no horizontal image x-axis) or at its own position.
photogrammetry::CameraPose station_pose(const SyntheticStation& station, const std::string& where);

}  // namespace rockface::camera
