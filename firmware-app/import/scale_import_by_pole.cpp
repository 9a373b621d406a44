#include "firmware-app/import/scale_import_by_pole.h"

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "storage/project/model_registration.h"

namespace rockface::app {

namespace {

using nlohmann::json;

// The target's pixel in the import's view (the visit's photograph), where
// the Model screen rings it, as `import --pole` records it.
json view_pixel(storage::ProjectStore& store, const storage::Model& m, const Eigen::Vector3d& p) {
  if (!m.camera_to_mesh || !m.texture_capture_id) return nullptr;
  for (const auto& c : store.list_captures())
    if (c.id == *m.texture_capture_id && c.calibration_id) {
      const auto k = store.load_calibration(*c.calibration_id).intrinsics;
      const photogrammetry::Similarity& cam = *m.camera_to_mesh;
      const Eigen::Vector3d q = cam.R.transpose() * (p - cam.t) / cam.scale;
      if (!(q.z() > 0)) return nullptr;
      return {k.fx * q.x() / q.z() + k.cx, k.fy * q.y() / q.z() + k.cy};
    }
  return nullptr;
}

// The import's parameters with the pole's registration in place of "none".
std::string with_pole(storage::ProjectStore& store, const storage::Model& m, const ImportPole& pole,
                      double length_m, const photogrammetry::Similarity& transform) {
  json p =
      json::parse(m.registration.parameters_json.empty() ? "{}" : m.registration.parameters_json,
                  nullptr, false);
  if (!p.is_object()) p = json::object();
  json targets = json::array();
  const char* which[2] = {"lower", "upper"};
  const Eigen::Vector3d ends[2] = {pole.lower, pole.upper};
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d world = transform.apply(ends[k]);
    json t = {{"which", which[k]},
              {"file", {ends[k].x(), ends[k].y(), ends[k].z()}},
              {"world", {world.x(), world.y(), world.z()}}};
    if (json px = view_pixel(store, m, ends[k]); !px.is_null()) t["left_px"] = px;
    targets.push_back(t);
  }
  p["registration"] = {{"scale_source", "range pole"},
                       {"vertical_source", "range pole"},
                       {"north_source", "none"},
                       {"scaled", true},
                       {"scale", transform.scale},
                       {"range_pole",
                        {{"length_m", length_m},
                         {"targets", targets},
                         {"targets_from", "tapped on the tablet's 3D view"}}}};
  return p.dump();
}

}  // namespace

ImportScaledByPole scale_import_by_pole(storage::ProjectStore& store, storage::RecordId visit_id,
                                        const ImportPole& pole, double length_m) {
  const std::string where = "visit " + std::to_string(visit_id);
  const auto models = store.list_visit_models(visit_id);
  if (models.empty()) throw InputError(where, "has no 3D image to scale");
  if (const auto m = store.list_measurements(visit_id); !m.empty())
    throw InputError(where, "already has " + std::to_string(m.size()) +
                                " measurements in its present frame: scale it by the pole "
                                "before mapping on it");
  if (store.load_visit_placement(visit_id))
    throw InputError(where, "is placed in the tunnel already: scale it before placing it");
  std::vector<storage::Model> scaled;
  for (const auto& summary : models) {
    storage::Model m = store.load_model(summary.id);
    const storage::ModelRegistration reg = storage::read_model_registration(m.registration);
    if (reg.imported_from.empty())
      throw InputError(where, "3D image " + std::to_string(m.id) +
                                  " was reconstructed from photographs: its pole is found in "
                                  "them, not tapped");
    if (m.registration.kind != "none")
      throw InputError(where, "3D image " + std::to_string(m.id) + " is registered already (" +
                                  m.registration.kind + ")");
    scaled.push_back(std::move(m));
  }
  // The first 3D image's view is the one the targets were tapped on; every
  // 3D image of the visit is in the same (the file's) frame.
  const photogrammetry::Similarity camera =
      scaled.front().camera_to_mesh.value_or(photogrammetry::Similarity{});
  const ImportPoleRegistration reg = register_import_to_pole(pole, length_m, std::nullopt, camera);
  for (storage::Model& m : scaled) {
    m.registration.parameters_json = with_pole(store, m, pole, length_m, reg.transform);
    for (auto& v : m.mesh.vertices) v = reg.transform.apply(v);
    storage::set_similarity(m.registration,
                            storage::similarity_of(m.registration).then(reg.transform));
    if (m.camera_to_mesh) m.camera_to_mesh = m.camera_to_mesh->then(reg.transform);
    m.registration.kind = storage::registration_kind("range pole", "none");
    m.id = 0;
    m.created_at.clear();
  }
  ImportScaledByPole out;
  out.scale = reg.transform.scale;
  out.note = "scaled and levelled by the range pole (" + format_fixed(length_m, 3) +
             " m between its targets tapped on the 3D view, scale " +
             format_significant(reg.transform.scale, 6) + ")";
  store.in_one_transaction("scaling " + where + " by the range pole", [&] {
    for (storage::Model& m : scaled) store.save_model(m);
    store.log_action(visit_id, "range pole", out.note);
  });
  return out;
}

}  // namespace rockface::app
