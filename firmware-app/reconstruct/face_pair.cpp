#include "firmware-app/reconstruct/face_pair.h"

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "firmware-app/records/project_mesh.h"
#include "storage/project/model_registration.h"
#include "storage/report/reconstruction_report.h"

namespace rockface::app {

storage::Model face_image_model(const photogrammetry::FaceRegistration& face, std::size_t index,
                                const photogrammetry::FaceImage& image,
                                const photogrammetry::Similarity& camera_to_image,
                                storage::RecordId capture_id, const std::string& preset_name) {
  const photogrammetry::ImageResidual& r = face.images.at(index);
  photogrammetry::SurfaceMesh mesh = image.mesh;
  mesh.transform(r.to_face.scale, r.to_face.R, r.to_face.t);
  storage::Model model;
  model.capture_id = capture_id;
  model.preset = preset_name;
  model.mesh = project_mesh(mesh);
  model.texture_capture_id = capture_id;
  model.texture_side = "left";
  model.registration.kind = "face_images";
  storage::set_similarity(model.registration, r.to_face);
  // The face registration report, with this pair's predicted precision of
  // a picked point (metres in the face frame), as a first model has.
  nlohmann::json parameters = nlohmann::json::parse(storage::face_registration_json(face));
  parameters["predicted_depth_sigma_mm"] = image.sigma_z * r.to_face.scale * 1000;
  model.registration.parameters_json = parameters.dump();
  model.registration.rms_m = r.surface_rms_m;
  // Its photographs' views: the pair's camera frame onto its 3D image, then
  // onto the face.
  model.camera_to_mesh = camera_to_image.then(r.to_face);
  return model;
}

std::optional<storage::Model> visit_face_model(storage::ProjectStore& store,
                                               storage::RecordId visit_id,
                                               storage::RecordId capture_id) {
  for (const auto& c : store.list_captures(visit_id)) {
    if (c.id == capture_id) continue;
    for (const auto& m : store.list_models(c.id)) {
      if (m.registration_kind == "none" || m.registration_kind == "face_images") continue;
      storage::Model model = store.load_model(m.id);
      if (model.texture_capture_id && model.camera_to_mesh && !model.mesh.vertices.empty())
        return model;
    }
  }
  return std::nullopt;
}

storage::Model face_pair_model(storage::ProjectStore& store, storage::Model face,
                               storage::RecordId capture_id, const cv::Mat& left,
                               const photogrammetry::ReconstructionResult& rec,
                               const photogrammetry::ReconstructionPreset& preset,
                               Progress& progress) {
  const std::string face_name = "capture " + std::to_string(*face.texture_capture_id);
  const storage::ImageBlob photo = store.load_capture_image(*face.texture_capture_id, "left");
  cv::Mat face_left = cv::imdecode(photo.bytes, cv::IMREAD_COLOR);
  if (face_left.empty())
    throw InputError(face_name + " left", "the stored image cannot be decoded");
  // The face model's precision of a point, in its (metric) frame: from its
  // reconstruction report; without one, its point spacing stands in (the
  // registration uses it only to weigh the surfaces' residuals).
  const storage::ModelRegistration registration =
      storage::read_model_registration(face.registration);
  photogrammetry::FaceImage first{
      face_name, face_left, surface_mesh(std::move(face.mesh), face_left.cols, face_left.rows),
      0.0};
  first.sigma_z = registration.predicted_depth_sigma_mm
                      ? *registration.predicted_depth_sigma_mm / 1000
                      : first.mesh.median_edge_length();
  const photogrammetry::FaceImage further{"capture " + std::to_string(capture_id), left, rec.mesh,
                                          rec.accuracy.sigma_z};
  progress.step("registering to " + face_name, 0.9);
  const photogrammetry::FaceRegistration registered =
      photogrammetry::register_face_images({first, further}, {}, preset, {}, progress);
  return face_image_model(registered, 1, further, rec.model_to_world, capture_id, preset.name);
}

}  // namespace rockface::app
