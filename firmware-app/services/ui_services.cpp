#include "firmware-app/services/ui_services.h"

#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "camera/gphoto2_camera.h"
#include "camera/mock_camera.h"
#include "camera/synthetic_renderer.h"
#include "core/analysis/preset_options.h"
#include "core/analysis/scene_analysis.h"
#include "core/common/error.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "firmware-app/import/scale_import_by_pole.h"
#include "firmware-app/reconstruct/face_pair.h"
#include "firmware-app/records/field_records.h"
#include "firmware-app/records/orient_visit.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "storage/scene/scene.h"

namespace rockface::app {

namespace {

namespace fs = std::filesystem;

cv::Mat decode_stored(const storage::ImageBlob& blob, const std::string& where) {
  cv::Mat image = cv::imdecode(blob.bytes, cv::IMREAD_COLOR);
  if (image.empty()) throw InputError(where, "the stored image cannot be decoded");
  return image;
}

}  // namespace

storage::RecordId StoreReconstructionRunner::reconstruct(const fs::path& project,
                                                         storage::RecordId capture_id,
                                                         Preset chosen, Progress& progress) {
  progress.step("reading the pair", 0.01);
  storage::ProjectStore store = storage::ProjectStore::open(project);
  const storage::Capture capture = store.load_capture(capture_id);
  const std::string where = "capture " + std::to_string(capture_id);
  if (!capture.calibration_id)
    throw InputError(where, "no calibration of the camera in the project (calibrate first)");
  const photogrammetry::CameraIntrinsics k =
      store.load_calibration(*capture.calibration_id).intrinsics;
  const cv::Mat left = decode_stored(capture.left, where + " left");
  const cv::Mat right = decode_stored(capture.right, where + " right");
  photogrammetry::RegistrationSources sources;
  if (const auto it = capture.settings.find("range_pole_m"); it != capture.settings.end())
    sources.range_pole_m = std::stod(it->second);
  auto preset = analysis::preset_options(chosen).reconstruction;
  // In a tunnel every visit is a round measured against the design: its
  // lining, seen along the drive, is matched for it (preset.h).
  preset.lining_along_the_drive = store.load_tunnel().has_value();
  auto rec = photogrammetry::reconstruct(left, right, k, k, preset, sources, progress);
  // A further pair of a visit that has its 3D image already (the left and
  // right pairs of a face beside the middle one, issue 45) is tied to that
  // image as a replay ties a scene's further pairs, so the visit is one face
  // in one frame whichever pairs saw the pole. A pair that overlaps it too
  // little (another face, a pair taken again from elsewhere) keeps its own
  // registration, and its report says why it was not tied.
  if (auto face = visit_face_model(store, capture.visit_id, capture_id)) {
    const storage::RecordId face_id = face->id;
    try {
      const storage::Model model =
          face_pair_model(store, std::move(*face), capture_id, left, rec, preset, progress);
      progress.step("saving the model", 0.99);
      return store.save_model(model);
    } catch (const InputError& e) {
      rec.accuracy.warnings.push_back("not tied to the visit's 3D image " +
                                      std::to_string(face_id) + ": " + e.what() +
                                      "; registered on its own");
    }
  }
  progress.step("saving the model", 0.99);
  return store.save_model(model_record(rec, capture_id,
                                       {where + " left", where + " right", preset.name,
                                        sources.range_pole_m, sources.baseline_m, sources.north}));
}

std::string StoreNorthRunner::orient(const fs::path& project, storage::RecordId visit_id,
                                     const Eigen::Vector2d& from_px, const Eigen::Vector2d& to_px,
                                     double bearing_deg, double declination_deg,
                                     Progress& progress) {
  progress.step("turning the visit to north", 0.1);
  photogrammetry::NorthReference north;
  north.from_px = from_px;
  north.to_px = to_px;
  north.azimuth_deg = bearing_deg;
  north.declination_deg = declination_deg;
  north.where = "the compass line tapped on the photograph";
  storage::ProjectStore store = storage::ProjectStore::open(project);
  const VisitOrientation done = orient_visit_by_compass(store, visit_id, north);
  return done.note;
}

std::string StorePoleRunner::scale(const fs::path& project, storage::RecordId visit_id,
                                   const Eigen::Vector3d& lower, const Eigen::Vector3d& upper,
                                   double length_m, Progress& progress) {
  progress.step("scaling the visit by the range pole", 0.1);
  storage::ProjectStore store = storage::ProjectStore::open(project);
  return scale_import_by_pole(store, visit_id, ImportPole{lower, upper}, length_m).note;
}

storage::RecordId StoreAnalysisRunner::analyse(const fs::path& project, storage::RecordId visit_id,
                                               Progress& progress) {
  progress.step("reading the visit", 0.01);
  storage::ProjectStore store = storage::ProjectStore::open(project);
  const storage::SceneSource source = storage::load_scene_source(store, visit_id);
  // The analysis input straight from the visit's rows, checked as the scene
  // reader checks a scene (issue 37: no scene JSON text in between).
  const analysis::AnalysisInput input = storage::visit_analysis_input(
      source, project.string() + " visit " + std::to_string(visit_id));
  const analysis::Report report = analysis::analyse(input, progress);
  std::optional<storage::RecordId> model_id;
  const auto models = store.list_models();
  if (!models.empty()) model_id = models.back().id;
  progress.step("saving the analysis", 0.99);
  const storage::RecordId id =
      store.save_analysis(analysis_record(report, visit_id, model_id, input.analysis.preset));
  // Which stored traces it took as one (pieces of a joint marked on different pairs).
  std::string joined;
  for (const auto& t : storage::scene_traces(source.measurements)) {
    if (t.pieces.size() < 2) continue;
    joined += joined.empty() ? "" : "; ";
    joined += t.label + " =";
    for (const auto& piece : t.pieces) joined += " " + piece;
  }
  if (!joined.empty())
    store.log_action(visit_id, "analysis " + std::to_string(id) + " joined traces", joined);
  return id;
}

std::unique_ptr<camera::Camera> FieldCameraConnector::connect() {
  const fs::path spool = fs::temp_directory_path() / "rockface-ui-spool";
  if (source_.empty()) {
    camera::Gphoto2Camera::Options options;
    options.spool_dir = spool.string();
    fs::create_directories(spool);
    return std::make_unique<camera::Gphoto2Camera>(options);
  }
  if (fs::is_directory(source_)) return camera::MockCamera::replay(source_, spool.string());
  const storage::Scene scene = storage::load_scene(source_);
  return camera::MockCamera::synthetic(synthetic_scene_from_scene(scene).scene, spool.string());
}

std::string FieldCameraConnector::describe() const {
  if (source_.empty()) return "DSLR over USB (libgphoto2)";
  if (fs::is_directory(source_)) return "mock camera: captures in " + source_;
  return "mock camera: synthetic scene " + fs::path(source_).filename().string();
}

}  // namespace rockface::app
