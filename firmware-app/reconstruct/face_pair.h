#pragma once
// A further stereo pair of a visit tied to the face its first 3D image set
// (issue 45). At the face a visit is three pairs, left, middle and right; the
// pair that sees the range pole is scaled (and, with a compass line,
// oriented) by it, and each further pair is registered to it as `rockface
// replay` registers a scene's further pairs: SIFT tie points between the
// left photographs lifted to both surfaces, a similarity, then ICP
// (core/photogrammetry/reconstruction/multi_image_registration.h). The
// further pair's model is stored in the first model's frame, registration
// kind `face_images`, with the face registration report and its predicted
// precision (docs/scene-extensions.md, "imaging.stations").
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "core/common/progress.h"
#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// The model of one registered image of a face registration: its mesh moved
// into the face frame, the registration report with its predicted
// precision, and its camera's pose (the pair's camera frame onto its own
// 3D image, then onto the face). `image` is the registration's image
// `index` (not the master).
storage::Model face_image_model(const photogrammetry::FaceRegistration& face, std::size_t index,
                                const photogrammetry::FaceImage& image,
                                const photogrammetry::Similarity& camera_to_image,
                                storage::RecordId capture_id, const std::string& preset_name);

// The 3D image of `visit_id` a further pair is tied to: the first model of
// an earlier capture of the visit that was registered on its own (by the
// pole, control points or a scanner's frame: not `none`, not itself a
// further pair) and keeps its photograph and its camera's pose, loaded (its
// mesh is what the pair is registered to). None when the visit has no such
// model (the pair is then the visit's first).
std::optional<storage::Model> visit_face_model(storage::ProjectStore& store,
                                               storage::RecordId visit_id,
                                               storage::RecordId capture_id);

// Registers the pair of `capture_id` (reconstructed: `rec`, its left
// photograph `left`) to the visit's face model `face` (visit_face_model) and
// returns the model to store. Throws InputError when the two do not overlap.
storage::Model face_pair_model(storage::ProjectStore& store, storage::Model face,
                               storage::RecordId capture_id, const cv::Mat& left,
                               const photogrammetry::ReconstructionResult& rec,
                               const photogrammetry::ReconstructionPreset& preset,
                               Progress& progress);

}  // namespace rockface::app
