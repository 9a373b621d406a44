#pragma once
// Picks (storage/picks.h) measured on a 3D image with core/measure: traces
// (taps, 3D points, or semi-automatic between two end pixels), areas and
// points, the joint planes of the traces grouped by joint, and the joint
// sets. Shared by `rockface measure` and `rockface replay`; the output format
// (rockface-measures/1) is in docs/scene-extensions.md.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/measure/joint_sets.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/plane_measurement.h"
#include "core/photogrammetry/trace_pieces.h"
#include "storage/picks.h"
#include "storage/project_records.h"

namespace rockface::app {

struct MeasureContext {
  const measure::MeshPicker* picker = nullptr;      // on the mesh, datum-relative
  std::map<std::string, measure::PhotoView> views;  // "left", "right" where known
  // Taps in a photograph named here are lifted onto this 3D image instead
  // (a further stereo pair of the visit, registered into the same frame).
  std::map<std::string, const measure::MeshPicker*> pickers;
  std::map<std::string, cv::Mat> photos;  // the photographs, for semi-automatic tracing
  measure::MeasureSettings settings;
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();  // the picks' 3D points are absolute
  std::string source;                               // the picks' file, for messages
};

// The name of a pair's photograph in MeasureContext (views, pickers,
// photos) and in the stored measurements: "left" / "right" for the first
// pair, "pair 2 left" for a further one.
std::string pair_photo(int pair, const std::string& side);

// The pair of a photograph named by pair_photo (1 for "left", "right" and
// for none).
int pair_of_photo(const std::string& photo);

// The picks with each further pair's photograph named by pair_photo, so
// that they are measured through that pair's view and on its 3D image.
storage::Picks picks_by_pair_photo(storage::Picks picks);

struct MeasuredTrace {
  measure::TraceMeasurement m;
  std::string joint;                  // as picked; empty when unassigned
  std::string cost;                   // semi-automatic: the cost used; empty otherwise
  double mean_cost = 0;               // semi-automatic: per pixel step, [0, 1]
  std::vector<Eigen::Vector2d> taps;  // what was picked (the ends for semi-automatic)
};

struct MeasuredArea {
  measure::AreaMeasurement m;
  std::string rock_side;
};

// The traces of one joint fitted together (a joint marked piece by piece).
struct MeasuredJoint {
  std::string label;
  std::vector<std::string> traces;
  measure::PlaneEstimate plane;
};

// Pieces of one joint trace measured on different pairs' 3D images (in the
// face frame), joined into one trace (photogrammetry::join_trace_pieces).
struct JoinedTrace {
  photogrammetry::FaceTrace face;  // its points (face frame) and pieces (trace ids)
  measure::PlaneEstimate plane;    // fitted to the measured samples of all pieces
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
  std::vector<measure::PointMeasurement> points;
  std::vector<MeasuredJoint> joints;
  // Pieces of one trace in different pairs' photographs, joined: in the set
  // statistics (and the stereonet) a joined trace is one pole, with its
  // whole length, in place of its pieces.
  std::vector<JoinedTrace> joined;
  std::vector<PoleSource> poles;
  measure::PoleClusters clusters;  // set_of per entry of `poles`
  std::vector<measure::JointSetSummary> sets;
  // The set label of a measurement id; empty when it is in no set (a
  // joined trace is named by its first piece).
  std::string set_of(const std::string& id) const;
  // The id and the plane of pole k.
  const std::string& pole_id(std::size_t k) const;
  const measure::PlaneEstimate& pole_plane(std::size_t k) const;
};

// Measures every pick; nothing is partial: the first bad pick throws
// InputError naming context.source and its field path. `sets`: the number
// of joint sets wanted, 0 or none for automatic.
MeasuredPicks measure_picks(const storage::Picks& picks, const MeasureContext& context,
                            std::optional<int> sets);

// The measured traces as pieces in the face frame: their measured points,
// each on the pair of its photograph (the first pair for 3D points).
std::vector<photogrammetry::TracePiece> trace_pieces(const MeasuredPicks& measured);

// Of `faces` (join_trace_pieces of pieces named by the traces of
// `measured`), the ones whose pieces lie on different pairs, each with the
// plane fitted to all its pieces' measured samples and its length.
std::vector<JoinedTrace> joined_traces(std::vector<photogrammetry::FaceTrace> faces,
                                       const MeasuredPicks& measured,
                                       const measure::MeasureSettings& settings);

// "T1: one trace across the pairs' photographs (T1, T4)".
std::string joined_note(const JoinedTrace& joined);

// rockface-measures/1 (docs/scene-extensions.md); coordinates absolute.
// `model`: the first pair's 3D image; `further_models` a further pair's by
// its photographs' names (pair_photo): each measurement names its own.
std::string measures_json(const MeasuredPicks& measured, const MeasureContext& context,
                          const std::string& model,
                          const std::map<std::string, std::string>& further_models = {});

// The model and capture of one pair of the visit: what a measurement taken
// in its photograph is stored with.
struct PairRecords {
  std::optional<storage::RecordId> model_id, capture_id;
};

// The measurements as project records (datum-relative points, the photo and
// pixels they came from; points only with a known plane) and the joint table: one joint per known
// plane of a trace, area or point, with its set, and the sets. Each
// measurement carries the model and capture of its photograph's pair:
// `first` for "left" / "right" and for 3D points, `further` by photograph
// name (pair_photo) for a further pair's.
std::vector<storage::Measurement> measurement_records(
    const MeasuredPicks& measured, storage::RecordId visit_id, const PairRecords& first,
    const std::map<std::string, PairRecords>& further = {});
std::vector<storage::JointSet> joint_set_records(const MeasuredPicks& measured);
std::vector<storage::Joint> joint_records(const MeasuredPicks& measured,
                                          storage::RecordId visit_id);

// The measurement records with each joined trace's pieces replaced by one
// trace record (the first piece's, with the joined points and plane).
void join_trace_records(const std::vector<JoinedTrace>& joined,
                        std::vector<storage::Measurement>& records);
// The joint table likewise: a further piece's joint goes, the first piece's
// takes the joined plane (persistence: the joined length), or goes when
// that plane is unknown.
void join_trace_joints(const std::vector<JoinedTrace>& joined, std::vector<storage::Joint>& joints);

}  // namespace rockface::app
