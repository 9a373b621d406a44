#include "firmware-app/replay/replay_more_pairs.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "camera/capture_guidance.h"
#include "camera/mock_camera.h"
#include "firmware-app/records/project_mesh.h"
#include "firmware-app/replay/replay_capture.h"
#include "storage/report/reconstruction_report.h"

namespace rockface::app {

namespace {

// Maps progress of one pair onto its share of the whole.
class PairProgress final : public Progress {
 public:
  PairProgress(Progress& outer, std::string pair) : outer_(outer), pair_(std::move(pair)) {}
  void report(std::string_view stage, double f) override {
    outer_.report(pair_ + ": " + std::string(stage), f);
  }
  bool cancel_requested() const override { return outer_.cancel_requested(); }

 private:
  Progress& outer_;
  std::string pair_;
};

std::string pair_name(std::size_t k) {
  return "pair " + std::to_string(k + 1);
}

}  // namespace

MorePairsOutcome replay_more_pairs(storage::ProjectStore& store, const MorePairsRequest& request,
                                   const cv::Mat& master_left,
                                   const photogrammetry::ReconstructionResult& master,
                                   Progress& progress) {
  namespace fs = std::filesystem;
  const SyntheticSceneInput& synthetic = *request.synthetic;
  MorePairsOutcome out;
  std::vector<photogrammetry::FaceImage> images;
  images.push_back({pair_name(0), master_left, master.mesh, master.accuracy.sigma_z});
  out.model_to_image.push_back(master.model_to_world);

  for (std::size_t k = 1; k < synthetic.pairs.size(); ++k) {
    PairProgress p(progress, pair_name(k));
    p.step("capture", 0.0);
    camera::SyntheticScene scene = synthetic.scene;
    scene.stations = synthetic.pairs[k];
    const fs::path spool = fs::path(request.spool) / pair_name(k);
    auto cam = camera::MockCamera::synthetic(scene, spool.string());
    cam->lock_focus();
    const camera::Capture left = cam->capture();
    const camera::Capture right = cam->capture();
    camera::require_same_optics(left.exif, right.exif);

    storage::Capture capture;
    capture.visit_id = request.visit_id;
    capture.calibration_id = request.calibration_id;
    capture.label = "replay " + pair_name(k);
    capture.left.bytes = left.image.data;
    capture.right.bytes = right.image.data;
    capture.left_exif = camera::exif_fields(left.exif);
    capture.right_exif = camera::exif_fields(right.exif);
    capture.settings["preset"] = request.preset_name;
    out.capture_ids.push_back(store.save_capture(capture));

    // Unregistered (levelled camera frame, units of the base): the face
    // registration below gives it scale, orientation and position.
    const cv::Mat left_image = decode_shot(left.image, pair_name(k) + " left");
    const cv::Mat right_image = decode_shot(right.image, pair_name(k) + " right");
    const photogrammetry::ReconstructionResult rec = photogrammetry::reconstruct(
        left_image, right_image, request.intrinsics, request.intrinsics, request.preset, {}, p);
    images.push_back({pair_name(k), left_image, rec.mesh, rec.accuracy.sigma_z});
    out.model_to_image.push_back(rec.model_to_world);
  }

  progress.step("registering the pairs to pair 1", 0.75);
  out.face = photogrammetry::register_face_images(images, {}, request.preset, {}, progress);
  const std::string face_json = storage::face_registration_json(out.face);
  for (std::size_t k = 1; k < images.size(); ++k) {
    const auto& r = out.face.images[k];
    photogrammetry::SurfaceMesh mesh = images[k].mesh;
    mesh.transform(r.to_face.scale, r.to_face.R, r.to_face.t);
    storage::Model model;
    model.capture_id = out.capture_ids[k - 1];
    model.preset = request.preset_name;
    model.mesh = project_mesh(mesh);
    model.texture_capture_id = model.capture_id;
    model.texture_side = "left";
    model.registration.kind = "face_images";
    storage::set_similarity(model.registration, r.to_face);
    // The face registration report, with this pair's predicted precision
    // of a picked point (metres in the face frame), as a first model has.
    nlohmann::json parameters = nlohmann::json::parse(face_json);
    parameters["predicted_depth_sigma_mm"] = images[k].sigma_z * r.to_face.scale * 1000;
    model.registration.parameters_json = parameters.dump();
    model.registration.rms_m = r.surface_rms_m;
    // Its photographs' views: the pair's camera frame onto its 3D image,
    // then onto the face.
    model.camera_to_mesh = out.model_to_image[k].then(r.to_face);
    out.model_ids.push_back(store.save_model(model));
  }
  out.images = std::move(images);
  return out;
}

}  // namespace rockface::app
