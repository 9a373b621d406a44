#include "firmware-app/replay/replay_more_pairs.h"

#include <filesystem>

#include "camera/capture_guidance.h"
#include "camera/mock_camera.h"
#include "firmware-app/reconstruct/face_pair.h"
#include "firmware-app/replay/replay_capture.h"
#include "storage/project/calibration_library.h"

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
    storage::record_camera(capture, camera::photo_camera(left.exif));
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
  for (std::size_t k = 1; k < images.size(); ++k)
    out.model_ids.push_back(
        store.save_model(face_image_model(out.face, k, images[k], out.model_to_image[k],
                                          out.capture_ids[k - 1], request.preset_name)));
  out.images = std::move(images);
  return out;
}

}  // namespace rockface::app
