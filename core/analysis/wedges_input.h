#pragma once
// The wedge analysis around an excavation as values (docs/scene-extensions.md,
// "wedges"; storage/scene/scene_wedges.h reads them from a scene): which joint
// sets, the excavation's profile and axis, a trace-length limit, and the
// support (pattern bolts, shotcrete). Water and seismic loads come from the
// analysis input's effects as for every block.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/design_profile.h"

namespace rockface::analysis {

struct SceneWedgeSupportPlaces {
  bool roof = true, walls = true, floor = false, face = false;
};

struct SceneWedgeBolts {
  double length = 0, spacing = 0, capacity = 0;  // m, m, N
  std::optional<double> bond_strength;           // N/m
  SceneWedgeSupportPlaces on;
};

struct SceneWedgeShotcrete {
  double thickness = 0, shear_strength = 0;  // m, Pa
  SceneWedgeSupportPlaces on{true, true, false, true};
};

struct SceneWedges {
  std::vector<std::string> sets;  // joint ids; empty: every joint of the scene
  // The profile: given here (a shape or a profile object / file), or the
  // scene tunnel's design profile ("tunnel", the default with a tunnel).
  std::optional<tunnel::DesignProfile> profile;
  std::string profile_source;             // "circle", "horseshoe", ..., "tunnel", a file name
  std::optional<double> trend, plunge;    // degrees; none: the tunnel's drive at `chainage`
  std::optional<double> chainage;         // m, with the scene's tunnel
  std::optional<Eigen::Vector3d> origin;  // absolute point of the axis at the section and face
  std::optional<double> trace_length;     // m
  bool perimeter = true, face = true;
  std::optional<SceneWedgeBolts> bolts;
  std::optional<SceneWedgeShotcrete> shotcrete;
};

}  // namespace rockface::analysis
