#include "firmware-app/tunnel/typed_placement.h"

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "firmware-app/tunnel/visit_placement.h"
#include "firmware-app/tunnel/visit_surface.h"
#include "storage/project/model_registration.h"

namespace rockface::app {

storage::VisitPlacement place_by_typed_chainage(storage::ProjectStore& store,
                                                storage::RecordId visit_id,
                                                const TypedChainage& typed) {
  const std::string where = "visit " + std::to_string(visit_id);
  const auto tunnel = store.load_tunnel();
  if (!tunnel)
    throw InputError(store.file().string(),
                     "the project has no tunnel: add its alignment and design profile first");
  const tunnel::Alignment alignment = tunnel->alignment(store.project().datum);
  const auto models = store.list_visit_models(visit_id);
  if (models.empty())
    throw InputError(where, "has no 3D image: reconstruct its photographs before placing it");
  if (const auto m = store.list_measurements(visit_id); !m.empty())
    throw InputError(where, "already has " + std::to_string(m.size()) +
                                " measurements in its present frame: place the visit before "
                                "mapping on it");
  // The pole's lower target in the first model (records/field_records.cpp
  // stores the targets in the project frame).
  const storage::ModelRegistration first =
      storage::read_model_registration(store.load_model(models.front().id).registration);
  if (first.targets_project.empty())
    throw InputError(where,
                     "its 3D image has no range pole targets: place it by monitoring targets "
                     "with survey coordinates instead");
  const Eigen::Vector3d lower = first.targets_project.front();
  const Eigen::Vector3d shift =
      tunnel::typed_pole_position(alignment, typed.chainage, typed.offset, typed.height) - lower;
  for (const auto& summary : models) {
    storage::Model m = store.load_model(summary.id);
    for (auto& v : m.mesh.vertices) v += shift;
    m.registration.translation += shift;
    if (m.camera_to_mesh) m.camera_to_mesh->t += shift;
    nlohmann::json params = nlohmann::json::parse(m.registration.parameters_json, nullptr, false);
    if (!params.is_discarded() && params.contains("targets") && params["targets"].is_array())
      for (auto& t : params["targets"])
        for (int k = 0; k < 3; ++k) t[k] = t[k].get<double>() + shift[k];
    if (!params.is_discarded()) m.registration.parameters_json = params.dump();
    m.id = 0;
    m.created_at.clear();
    store.save_model(m);
  }
  const std::string note = "chainage " + format_fixed(typed.chainage, 2) + ", offset " +
                           format_fixed(typed.offset, 2, " m") + " (typed)";
  const storage::VisitPlacement placement =
      place_visit(alignment, tunnel->profile, visit_surface(store, visit_id), visit_id, note);
  store.save_visit_placement(placement);
  return placement;
}

}  // namespace rockface::app
