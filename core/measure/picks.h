#pragma once
// What a geologist picked on the 3D image (`rockface measure --traces
// PICKS.json`, and a scene's `picks` for `rockface replay`): traces as taps
// in a photograph, as 3D points, or as two end pixels to trace between;
// areas as polygons; points. Format rockface-picks/1, described in
// docs/scene-extensions.md, read by storage/scene/picks_json.h.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/measure/compass_reading.h"
namespace rockface::measure {

struct TracePick {
  std::string id;
  std::string joint;  // the joint it belongs to; empty when unassigned
  std::string where;  // its field path, for messages ("traces[2]")
  // Exactly one of the three forms:
  std::string photo;  // "left" | "right" for pixels and ends
  // The stereo pair of the visit whose photograph `photo` is, counted from
  // 1 (imaging.stations in pairs); only the first pair's right photograph
  // and semi-automatic tracing are offered, a further pair takes taps in
  // its left photograph.
  int pair = 1;
  std::vector<Eigen::Vector2d> pixels;                 // taps along the trace
  std::vector<Eigen::Vector3d> points;                 // 3D points (absolute coordinates)
  std::optional<std::array<Eigen::Vector2d, 2>> ends;  // semi-automatic: trace between them
  std::string cost = "darkness";  // semi-automatic: darkness | gradient | curvature
  // Where the trace came from (issue 25): "hand" (tapped; the default),
  // "proposed" (a trace proposal accepted as found: `rockface propose`),
  // "corrected" (a proposal redrawn between its dragged ends).
  std::string origin = "hand";
  // A compass reading of the joint where the trace runs (issue 27): its
  // plane is then the reading's, checked against the trace
  // (compass_reading.h). Field `compass` {dip, dip_direction}.
  std::optional<CompassReading> compass;
};

struct AreaPick {
  std::string id;
  std::string where;
  std::string photo;
  int pair = 1;  // as for a trace: a further pair's area is outlined in its left photograph
  std::vector<Eigen::Vector2d> polygon;
  std::string rock_side;  // "upper" | "lower" when the area is a free face; empty otherwise
};

struct PointPick {
  std::string id;
  std::string where;
  std::string photo;
  int pair = 1;  // as for a trace: a further pair's point is tapped in its left photograph
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double radius = 0.1;  // m: the surface within it gives the local plane
};

struct Picks {
  std::vector<TracePick> traces;
  std::vector<AreaPick> areas;
  std::vector<PointPick> points;
  std::optional<int> sets;  // joint sets wanted; none or 0: automatic
};

}  // namespace rockface::measure
