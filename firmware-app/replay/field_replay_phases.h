#pragma once
// The phases of replay_field_workflow (field_replay.h), each a function of
// its own input, declared here so that each can be read and tested alone:
//   1. open_source: the scene and its synthetic camera, or the capture
//      folder and its camera.json; the preset; what registers the model;
//   2. capture_pair: the pair through the mock camera, optics checked;
//   3. store_capture: the camera body, its calibration and the pair;
//   4. reconstruct_pair: the 3D image, registered, moved onto the pole's
//      surveyed (or typed) place (move_to_pole);
//   5. replay_analysis_input: the scene's analysis input with the measured
//      traces and joints, else the synthetic truth's traces
//      (true_face_traces) and, in a rendered tunnel, its face
//      (rendered_face);
//   6. visit_measurements and visit_joints: what the visit stores so that it
//      can be analysed again from the project alone;
//   7. analyse and store the report (in replay_field_workflow).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "camera/camera.h"
#include "camera/mock_camera.h"
#include "camera/synthetic_scene.h"
#include "core/analysis/analysis_input.h"
#include "core/common/preset.h"
#include "core/measure/pick_measurement.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
#include "firmware-app/replay/field_replay.h"
#include "firmware-app/replay/replay_more_pairs.h"
#include "firmware-app/replay/replay_picks.h"
#include "storage/project/project_records.h"
#include "storage/project/project_store.h"
#include "storage/scene/scene.h"

namespace rockface::app::field_replay_phases {

// 1. What is replayed. A scene: its synthetic camera, the pole's typed place
// (tunnel.placement) and the registration's sources (range pole, compass
// line); a capture folder: its camera.json and no scene. Bad input (the
// source, the picks, a typed place off the alignment) is refused here,
// before the camera spools a shot or the project is created.
struct ReplaySource {
  std::optional<storage::Scene> scene;
  std::optional<SyntheticSceneInput> synthetic;  // with the scene
  std::optional<Eigen::Vector3d> typed_pole;     // the pole's lower target, datum-relative
  std::unique_ptr<camera::MockCamera> camera;
  photogrammetry::CameraIntrinsics intrinsics;
  photogrammetry::RegistrationSources sources;
  std::filesystem::path spool;  // beside the project: <project>.spool
  // --preset, else the scene's analysis.preset; a capture folder has no
  // scene, so its default is the scene's default (standard).
  Preset preset = Preset::standard;
  std::string visit_note;     // a folder's visit file's note
  std::string visit_heading;  // and its heading
  // The geologist who maps the visit: --geologist, else the visit file's.
  std::string visit_geologist;
  // A folder without camera.json: its photographs take the calibration of
  // their camera from the project's library (calibration_library.h), chosen
  // once the project is open (library_calibration).
  bool calibration_from_library = false;
  std::optional<storage::RecordId> library_calibration_id;  // the one chosen
};
ReplaySource open_source(const ReplayRequest& request);

// A folder's registration: the request's options, each else the visit
// file's (`visit_file`, when it exists), checked (registration_sources).
// `preset`, `note`, `heading` and `geologist` take the file's when it
// gives them.
photogrammetry::RegistrationSources folder_registration(const RegistrationOptions& given,
                                                        const std::filesystem::path& visit_file,
                                                        std::optional<Preset>& preset,
                                                        std::string& note, std::string& heading,
                                                        std::string& geologist);

// 2. Focus locked after the first shot; the two shots' optics must match
// (throws otherwise); `guidance`: the capture guidance's notes on the pair.
struct CapturedPair {
  camera::Capture left, right;
  std::vector<std::string> guidance;
};
CapturedPair capture_pair(camera::MockCamera& camera);

// 3. The camera body, the calibration the pair was taken with and the pair
// itself, stored in the visit.
struct StoredCapture {
  storage::RecordId calibration_id = 0, capture_id = 0;
};
StoredCapture store_capture(storage::ProjectStore& store, const ReplayRequest& request,
                            const ReplaySource& source, const CapturedPair& pair,
                            storage::RecordId visit_id, const std::string& preset_name);

// 3a. For a source that takes its calibration from the library: the
// calibration of the camera that took the left photograph; throws
// InputError naming the folder and saying what to do when none fits.
storage::Calibration library_calibration(storage::ProjectStore& store, const ReplayRequest& request,
                                         const CapturedPair& pair);

// 4. The pair reconstructed and registered; a scene's model then moved into
// the project frame (move_to_pole).
photogrammetry::ReconstructionResult reconstruct_pair(
    const cv::Mat& left_image, const cv::Mat& right_image, const ReplaySource& source,
    const photogrammetry::ReconstructionPreset& preset, Progress& progress);

// The registered frame has its origin at the pole (heading turned about the
// reference line); the scene surveys where the pole stood (or the geologist
// typed it, in a tunnel), so the model (mesh and model_to_world) shifts to
// put the pole's lower target at `pole`. Needs rec.targets.
// A model on control points is about their centroid (rec.datum); the
// project's frame about its datum: the model moved into it. Nothing for a
// model without control points (already in the replay's frame).
void rebase_to_datum(photogrammetry::ReconstructionResult& rec, const Eigen::Vector3d& datum);
void move_to_pole(photogrammetry::ReconstructionResult& rec, const Eigen::Vector3d& pole);

// The compass line of a synthetic scene (its reference_line): its bearing
// (degrees clockwise from north, of its horizontal projection) and its end
// points in the first station's left image, named in messages as the
// scene file `source`'s field. Nothing without a line.
std::optional<photogrammetry::NorthReference> compass_reading(
    const camera::SyntheticScene& scene, const photogrammetry::CameraIntrinsics& k,
    const std::string& source);

// The scene's monitoring targets (imaging.control_targets) as control
// points: each picked at its centre's pixel in the left photograph, its
// survey coordinates the scene's.
std::vector<photogrammetry::ControlPoint> scene_control_points(
    const SyntheticSceneInput& synthetic, const photogrammetry::CameraIntrinsics& k);

// Each scene joint that has picked traces: its measured plane beside the
// scene's.
std::vector<JointComparison> joint_comparisons(const storage::Scene& scene,
                                               const measure::MeasuredPicks& measured);

// 5. The traces the geologist would mark on the model when the scene gives
// neither picks nor traces: the synthetic scene's true traces, absolute,
// named T1, T2, ...; in a rendered tunnel only the face's (its walls are
// thousands of facets; the geologist maps the face).
std::vector<analysis::SceneTrace> true_face_traces(const storage::Scene& scene,
                                                   const SyntheticSceneInput& synthetic);

// A rendered tunnel's free surface: its face's patches (id FACE...),
// absolute.
std::vector<analysis::ScenePatch> rendered_face(const SyntheticSceneInput& synthetic);

// The analysis input, filled once from the scene and then with what was
// measured (`picked`, may be null): the measured traces and joint planes;
// without traces, true_face_traces; without patches in a rendered tunnel,
// rendered_face. Throws InputError naming `source_name` when there is no
// free surface.
analysis::AnalysisInput replay_analysis_input(const storage::Scene& scene,
                                              const SyntheticSceneInput& synthetic,
                                              const ReplayPicks* picked,
                                              const std::string& source_name);

// 6. The visit's traces and free surface (as areas), datum-relative: the
// picks' measurements, each with its own pair's model and capture (`more`:
// the further pairs, may be null), else the analysed traces; then every
// patch.
struct VisitRecordIds {
  storage::RecordId visit_id = 0, model_id = 0, capture_id = 0;
};
std::vector<storage::Measurement> visit_measurements(const analysis::AnalysisInput& analysed,
                                                     const ReplayPicks* picked,
                                                     const MorePairsOutcome* more,
                                                     const VisitRecordIds& ids,
                                                     const Eigen::Vector3d& datum);

// The visit's joints: the analysed ones, each from the scene or, where its
// picked traces gave its plane, from those traces ("traces T1 T2").
std::vector<storage::Joint> visit_joints(const analysis::AnalysisInput& analysed,
                                         const ReplayPicks* picked, storage::RecordId visit_id,
                                         const Eigen::Vector3d& datum);

}  // namespace rockface::app::field_replay_phases
