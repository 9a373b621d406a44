#pragma once
// The scene's `tunnel` section (docs/scene-extensions.md): the tunnel the
// visit lies in (alignment and design profile from the tunnel's files,
// drive, underbreak tolerance), the chainage the geologist types for the
// range pole when no surveyed point places the visit, and, for the mock
// camera, the round to render with its known over- and underbreak.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "storage/tunnel/tunnel_records.h"

namespace rockface::storage {

class Reader;

// Where the geologist stood the range pole, typed: its lower target's
// centre at a chainage, an offset (+ right of the axis looking in the drive
// direction) and a height above the alignment's axis, all in m.
struct SceneTunnelPlacement {
  double chainage = 0;
  double offset = 0;
  double height = 0;
};

// One smooth bump of the rendered surface off the design line (+ overbreak).
struct SceneTunnelBreak {
  double chainage_from = 0, chainage_to = 0;
  double s_from = 0, s_to = 0;  // m of design outline from its start
  double depth_m = 0;
};

struct SceneTunnelRender {
  double from_chainage = 0;  // the walls start here (behind the cameras)
  double face_chainage = 0;  // the face
  double section_m = 0.25;
  double facet_m = 0.1;
  double face_relief_m = 0;  // the face's centre bulges this far toward the cameras
  std::vector<SceneTunnelBreak> breaks;
};

struct SceneTunnel {
  TunnelRecord record;  // name, alignment table, profile, drive, tolerance
  std::optional<SceneTunnelPlacement> placement;
  std::optional<SceneTunnelRender> render;
};

// Reads `tunnel`; files named in it are relative to the scene file's folder.
// origin: the scene's datum (zero without one), which the alignment is
// checked against and built for once (the record keeps it).
SceneTunnel read_scene_tunnel(const Reader& r, const nlohmann::json& section,
                              const std::string& scene_path, const Eigen::Vector3d& origin);

}  // namespace rockface::storage
