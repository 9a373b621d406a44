#include "firmware-app/tunnel/visit_surface.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/project/model_registration.h"

namespace rockface::app {

namespace {

// The pole's two target centres in the project frame, from the model's
// registration parameters (records/field_records.cpp writes "targets").
std::vector<Eigen::Vector3d> pole_targets(const storage::Model& model) {
  std::vector<Eigen::Vector3d> out;
  if (model.registration.parameters_json.empty()) return out;
  const nlohmann::json p =
      nlohmann::json::parse(model.registration.parameters_json, nullptr, false);
  if (p.is_discarded() || !p.contains("targets") || !p["targets"].is_array()) return out;
  for (const auto& t : p["targets"])
    if (t.is_array() && t.size() == 3 && t[0].is_number() && t[1].is_number() && t[2].is_number())
      out.emplace_back(t[0].get<double>(), t[1].get<double>(), t[2].get<double>());
  return out;
}

}  // namespace

VisitSurface visit_surface(storage::ProjectStore& store, storage::RecordId visit_id,
                           const PoleMask& mask) {
  VisitSurface out;
  std::vector<Eigen::Vector3d> targets;
  bool every_sigma_known = true;
  double sigma = 0;
  for (const auto& summary : store.list_visit_models(visit_id)) {
    storage::Model model = store.load_model(summary.id);
    const storage::ModelRegistration reg = storage::read_model_registration(model.registration);
    if (reg.is_scaled() && reg.predicted_depth_sigma_mm && *reg.predicted_depth_sigma_mm > 0)
      sigma = std::max(sigma, *reg.predicted_depth_sigma_mm / 1000);
    else
      every_sigma_known = false;
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), model.mesh.vertices.begin(), model.mesh.vertices.end());
    for (const auto& f : model.mesh.faces)
      out.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    for (const auto& t : pole_targets(model)) targets.push_back(t);
    if (out.models++ == 0) {
      model.mesh = {};
      out.first = std::move(model);
    }
  }
  if (out.models == 0)
    throw InputError("visit " + std::to_string(visit_id),
                     "has no 3D image: reconstruct its photographs first");
  if (every_sigma_known) out.depth_sigma_m = sigma;
  out.not_rock.assign(out.vertices.size(), 0);
  if (targets.size() >= 2) {
    // The pole is vertical (it is levelled in the field; the registration
    // takes the vertical from it): a vertical cylinder through the targets.
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();
    double low = targets[0].z(), high = targets[0].z();
    for (const auto& t : targets) {
      axis += t.head<2>();
      low = std::min(low, t.z());
      high = std::max(high, t.z());
    }
    axis /= static_cast<double>(targets.size());
    for (std::size_t i = 0; i < out.vertices.size(); ++i) {
      const auto& v = out.vertices[i];
      if ((v.head<2>() - axis).norm() <= mask.radius_m && v.z() >= low - mask.below_m &&
          v.z() <= high + mask.above_m) {
        out.not_rock[i] = 1;
        ++out.pole_vertices;
      }
    }
  }
  return out;
}

tunnel::SurfaceInput surface_input(const VisitSurface& surface) {
  tunnel::SurfaceInput input;
  input.vertices = surface.vertices;
  input.triangles = surface.triangles;
  input.not_rock_vertex = surface.not_rock;
  return input;
}

}  // namespace rockface::app
