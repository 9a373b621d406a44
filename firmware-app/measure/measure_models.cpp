#include "firmware-app/measure/measure_models.h"

#include <algorithm>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/common/preset.h"
#include "core/measure/pair_photo.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "firmware-app/records/project_mesh.h"
#include "storage/exchange/ply_reader.h"
#include "storage/scene/camera_json.h"

namespace rockface::app {

namespace {

cv::Mat decode(const std::vector<unsigned char>& bytes) {
  if (bytes.empty()) return {};
  try {
    return cv::imdecode(bytes, cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    return {};
  }
}

}  // namespace

LoadedModel load_ply_model(const ModelSource& o) {
  if (o.camera.empty())
    throw InputError("--camera",
                     "a model file needs the calibration of the camera it was "
                     "reconstructed with (the --camera of `rockface reconstruct`)");
  const photogrammetry::CameraIntrinsics camera = storage::load_camera_json(o.camera);
  storage::PlyModel ply = storage::read_ply_mesh(o.source);
  LoadedModel m;
  m.datum = ply.datum;
  m.name = o.source;
  m.mesh = surface_mesh(std::move(ply.mesh), camera.width, camera.height);
  if (m.mesh.triangles.empty()) throw InputError(o.source, "the model has no triangles");
  if (m.mesh.pixels.empty())
    throw InputError(o.source,
                     "the model has no texture coordinates: its vertices cannot be "
                     "placed in the left photograph");
  m.views.emplace("left", measure::left_view_from_lattice(m.mesh, camera));
  const std::string photo = !o.photo.empty() ? o.photo : ply.texture_file;
  if (!photo.empty()) {
    m.photos["left"] = cv::imread(photo, cv::IMREAD_COLOR);
    if (!o.photo.empty() && m.photos["left"].empty())
      throw InputError("--photo", photo + " is not an image OpenCV can read");
  }
  // Without a report: the point precision given, else a tenth of a percent
  // of the distance to the face (sigma_Z of a 1/5 base at 0.2 px).
  const double distance = (m.views["left"].pose.centre - m.mesh.vertices[m.mesh.size() / 2]).norm();
  m.point_sigma = o.point_sigma.value_or(1e-3 * distance);
  m.correlation_length =
      m.mesh.median_edge_length() * photogrammetry::preset_standard().sgbm_block_size;
  return m;
}

LoadedModel load_stored_model(storage::ProjectStore& store, const ModelSource& o,
                              storage::RecordId id, int pair) {
  storage::Model model;
  try {
    model = store.load_model(id);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError("--model", "no model " + std::to_string(id) + " in " + o.source);
  }
  LoadedModel m;
  m.model_id = id;
  m.name = o.source + " model " + std::to_string(id);
  m.datum = store.project().datum;
  if (!model.texture_capture_id || model.texture_side != "left")
    throw InputError(o.source, "model " + std::to_string(id) +
                                   " has no left photograph as texture: picks in a photograph "
                                   "cannot be placed on it");
  if (!model.camera_to_mesh)
    throw InputError(o.source, "model " + std::to_string(id) +
                                   " keeps no pose of its camera (a further pair stored before "
                                   "schema 4): replay the visit again to measure on it");
  m.capture_id = model.texture_capture_id;
  const storage::Capture capture = store.load_capture(*model.texture_capture_id);
  if (!capture.calibration_id)
    throw InputError(o.source,
                     "the capture of model " + std::to_string(id) + " has no calibration");
  const auto intrinsics = store.load_calibration(*capture.calibration_id).intrinsics;
  const photogrammetry::Similarity& camera_to_mesh = *model.camera_to_mesh;
  auto add_view = [&](measure::PhotoView view, const std::vector<unsigned char>& bytes) {
    const std::string name = measure::pair_photo(pair, view.name);
    view.name = name;
    m.views.emplace(name, std::move(view));
    m.photos[name] = decode(bytes);
  };
  add_view(measure::left_view(camera_to_mesh, intrinsics), capture.left.bytes);
  // The report of the reconstruction: the right camera's relative
  // orientation and the predicted precision of a point.
  const storage::Registration& r = model.registration;
  const auto p =
      nlohmann::json::parse(r.parameters_json.empty() ? "{}" : r.parameters_json, nullptr, false);
  if (p.is_object() && p.contains("orientation") && p["orientation"].contains("R") &&
      p["orientation"].contains("t")) {
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) R(i, k) = p["orientation"]["R"][i][k].get<double>();
      t[i] = p["orientation"]["t"][i].get<double>();
    }
    add_view(measure::right_view(camera_to_mesh, R, t, intrinsics), capture.right.bytes);
  }
  m.mesh = surface_mesh(std::move(model.mesh), intrinsics.width, intrinsics.height);
  if (m.mesh.triangles.empty())
    throw InputError(o.source, "model " + std::to_string(id) + " has no triangles");
  m.point_sigma = o.point_sigma.value_or(p.is_object() && p.contains("predicted_depth_sigma_mm")
                                             ? p["predicted_depth_sigma_mm"].get<double>() / 1000
                                             : 0.01);
  // A stored name is decoded like any other; an empty one (the column is NOT
  // NULL and every writer names the preset, but a project written by another
  // tool may leave it blank) keeps the behaviour the measure verb had since
  // it came: the standard preset's window, since refusing would make a
  // stored model unmeasurable for a label that only sizes a correlation length.
  const auto preset = photogrammetry::reconstruction_preset(
      model.preset.empty() ? Preset::standard
                           : parse_preset(model.preset, "model " + std::to_string(id) + " preset"));
  m.correlation_length = m.mesh.median_edge_length() * preset.sgbm_block_size;
  return m;
}

ProjectPairs project_pairs(storage::ProjectStore& store, const ModelSource& o) {
  if (o.model && o.visit)
    throw InputError("--model", "give --model (one 3D image) or --visit (its pairs), not both");
  if (o.model) return {{*o.model}, "model " + std::to_string(*o.model)};
  const auto visits = store.list_visits();
  if (o.visit) {
    if (std::none_of(visits.begin(), visits.end(),
                     [&](const storage::Visit& v) { return v.id == *o.visit; }))
      throw InputError("--visit", "no visit " + std::to_string(*o.visit) + " in " + o.source);
    ProjectPairs out{{}, "visit " + std::to_string(*o.visit)};
    for (const auto& m : store.list_visit_models(*o.visit)) out.models.push_back(m.id);
    if (out.models.empty())
      throw InputError("--visit", "visit " + std::to_string(*o.visit) + " of " + o.source +
                                      " has no model to measure on");
    return out;
  }
  for (auto v = visits.rbegin(); v != visits.rend(); ++v) {
    ProjectPairs out{{}, "visit " + std::to_string(v->id)};
    for (const auto& m : store.list_visit_models(v->id)) out.models.push_back(m.id);
    if (!out.models.empty()) return out;
  }
  throw InputError(o.source, "the project has no model to measure on");
}

}  // namespace rockface::app
