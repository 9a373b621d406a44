#pragma once
// The further stereo pairs of one visit in `rockface replay`: a scene whose
// imaging.stations lists more than two stations is photographed pair by pair
// (docs/scene-extensions.md). Each further pair is captured through the mock
// camera, reconstructed unregistered, registered to the first pair's 3D image
// (multi_image_registration.h) and stored as a capture and a model of the
// visit, its mesh in the face frame (the first model's frame).
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
#include "storage/project/project_store.h"

namespace rockface::app {

struct MorePairsRequest {
  storage::RecordId visit_id = 0, calibration_id = 0;
  const SyntheticSceneInput* synthetic = nullptr;  // pairs[1..] are photographed
  photogrammetry::CameraIntrinsics intrinsics;
  std::string preset_name;
  photogrammetry::ReconstructionPreset preset;
  std::string spool;  // folder for the captured files
};

struct MorePairsOutcome {
  std::vector<storage::RecordId> capture_ids, model_ids;  // of the further pairs
  photogrammetry::FaceRegistration face;                  // every pair, the first included
  // Every pair's 3D image in its own frame (the first's is the face frame)
  // and the map from its camera model frame to that frame, for the views of
  // its photographs (the face frame is then reached with face.images[k].to_face).
  std::vector<photogrammetry::FaceImage> images;
  std::vector<photogrammetry::Similarity> model_to_image;
};

// `master` is the first pair's reconstruction (its frame is the face frame)
// and `master_left` its left photograph. Throws InputError naming a pair that
// overlaps none of the others.
MorePairsOutcome replay_more_pairs(storage::ProjectStore& store, const MorePairsRequest& request,
                                   const cv::Mat& master_left,
                                   const photogrammetry::ReconstructionResult& master,
                                   Progress& progress);

}  // namespace rockface::app
