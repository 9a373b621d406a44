#pragma once
// Picks (picks.h) measured on a 3D image: traces (taps, 3D points, or
// semi-automatic between two end pixels), areas and points, the joint
// planes of the traces grouped by joint, pieces of one trace in different
// pairs' photographs joined (joined_traces.h), and the joint sets. Shared by
// `rockface measure` and `rockface replay`.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "core/measure/compass_reading.h"
#include "core/measure/free_face_side.h"
#include "core/measure/joint_sets.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/photo_view.h"
#include "core/measure/picks.h"
#include "core/measure/plane_measurement.h"
#include "core/photogrammetry/surface/trace_pieces.h"

namespace rockface::measure {

struct MeasureContext {
  const MeshPicker* picker = nullptr;      // on the mesh, datum-relative
  std::map<std::string, PhotoView> views;  // "left", "right" where known
  // Taps in a photograph named here are lifted onto this 3D image instead
  // (a further stereo pair of the visit, registered into the same frame).
  std::map<std::string, const MeshPicker*> pickers;
  std::map<std::string, cv::Mat> photos;  // the photographs, for semi-automatic tracing
  MeasureSettings settings;
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();  // the picks' 3D points are absolute
  std::string source;                               // the picks' file, for messages
};

struct MeasuredTrace {
  TraceMeasurement m;
  std::string joint;                  // as picked; empty when unassigned
  std::string cost;                   // semi-automatic: the cost used; empty otherwise
  double mean_cost = 0;               // semi-automatic: per pixel step, [0, 1]
  std::vector<Eigen::Vector2d> taps;  // what was picked (the ends for semi-automatic)
  std::string origin = "hand";        // as picked: "hand" | "proposed" | "corrected"
  // Its plane is a compass reading (the pick's): how the trace lies in it.
  std::optional<CompassCheck> compass;
};

struct MeasuredArea {
  MeasuredArea() = default;
  // An area measured elsewhere (a face outline's piece): its rock side as given.
  MeasuredArea(AreaMeasurement measured, std::string side)
      : m(std::move(measured)), rock_side(std::move(side)) {}

  AreaMeasurement m;
  // "upper" | "lower" when the area is a free face (free_face_side.h: from
  // the photograph, or the pick's where the photograph sees it edge-on);
  // empty otherwise. Its corners turn counter-clockwise seen from the air.
  std::string rock_side;
  // A free face: where its rock side came from ("photograph" | "pick"), and
  // marginal when the photograph sees it edge-on. Every area: how the
  // camera sees it (the angle is the rock side's margin).
  std::string rock_side_from;
  bool marginal = false;
  AreaSight sight;
};

// The traces of one joint fitted together (a joint marked piece by piece).
struct MeasuredJoint {
  std::string label;
  std::vector<std::string> traces;
  PlaneEstimate plane;
};

// Pieces of one joint trace measured on different pairs' 3D images (in the
// face frame), joined into one trace (photogrammetry::join_trace_pieces).
struct JoinedTrace {
  photogrammetry::FaceTrace face;  // its points (face frame) and pieces (trace ids)
  PlaneEstimate plane;             // fitted to the measured samples of all pieces
  double length = 0;               // m, along the joined points
  // An end of the joined trace (the piece end it is) lies at the edge of
  // the mapped area; the ends where pieces meet are not ends of the trace.
  bool censored = false;
};

// One pole in the set statistics: a known plane of a trace, an area that is
// not a free face, or a point.
struct PoleSource {
  char kind = 't';  // 't' trace, 'a' area, 'p' point, 'j' joined trace
  std::size_t index = 0;
};

struct MeasuredPicks {
  std::vector<MeasuredTrace> traces;
  std::vector<MeasuredArea> areas;
  std::vector<PointMeasurement> points;
  std::vector<MeasuredJoint> joints;
  // Pieces of one trace in different pairs' photographs, joined: in the set
  // statistics (and the stereonet) a joined trace is one pole, with its
  // whole length, in place of its pieces.
  std::vector<JoinedTrace> joined;
  std::vector<PoleSource> poles;
  PoleClusters clusters;  // set_of per entry of `poles`
  std::vector<JointSetSummary> sets;
  // The set label of a measurement id; empty when it is in no set (a
  // joined trace is named by its first piece).
  std::string set_of(const std::string& id) const;
  // The id and the plane of pole k.
  const std::string& pole_id(std::size_t k) const;
  const PlaneEstimate& pole_plane(std::size_t k) const;
};

// Measures every pick; nothing is partial: the first bad pick throws
// InputError naming context.source and its field path. `sets`: the number
// of joint sets wanted, 0 or none for automatic.
MeasuredPicks measure_picks(const Picks& picks, const MeasureContext& context,
                            std::optional<int> sets);

// What the picks can be checked for before anything is photographed, from
// the camera alone (every photograph width x height px): each tap, end and
// polygon corner inside its photograph, and the curvature cost only on the
// left photograph (the one the 3D image is seen from). Whether a tap has
// surface under it is known only from the 3D image (measure_picks). Throws
// InputError naming `source` and the pick's field ("...: picks.traces[2].
// pixels[1]: pixel (6100, 20) is outside the left photograph (6000 x 4000)").
void check_picks_in_photographs(const Picks& picks, int width, int height,
                                const std::string& source);

}  // namespace rockface::measure
