#include "firmware-app/tunnel/visit_surface.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/preset.h"
#include "core/photogrammetry/reconstruction/preset.h"
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

// The stereo pair a reconstructed model was made from, in the frame of its
// mesh: its left camera's centre and axis from the camera's map onto the
// mesh, the right camera from the relative orientation (x_right = R x_left
// + t, base 1 in the camera frame), the focal length and the disparity
// precision its report states.
std::optional<tunnel::StereoPairView> stereo_pair_of(const storage::Model& model) {
  if (!model.camera_to_mesh || model.registration.parameters_json.empty()) return std::nullopt;
  const nlohmann::json p =
      nlohmann::json::parse(model.registration.parameters_json, nullptr, false);
  if (p.is_discarded() || !p.contains("focal_px") || !p["focal_px"].is_number() ||
      !p.contains("disparity_sigma_px") || !p["disparity_sigma_px"].is_number() ||
      !p.contains("orientation") || !p["orientation"].contains("R") ||
      !p["orientation"].contains("t"))
    return std::nullopt;
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  try {
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) R(i, k) = p["orientation"]["R"][i][k].get<double>();
      t[i] = p["orientation"]["t"][i].get<double>();
    }
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  const photogrammetry::Similarity& cam = *model.camera_to_mesh;
  tunnel::StereoPairView view;
  view.left_centre = cam.apply(Eigen::Vector3d::Zero());
  view.right_centre = cam.apply(-R.transpose() * t);
  view.optical_axis = cam.R * Eigen::Vector3d::UnitZ();
  view.focal_px = p["focal_px"].get<double>();
  view.disparity_sigma_px = p["disparity_sigma_px"].get<double>();
  if (!(view.focal_px > 0) || !(view.disparity_sigma_px > 0)) return std::nullopt;
  // The dense matching's window: the preset the model was made with.
  try {
    view.window_px =
        photogrammetry::reconstruction_preset(parse_preset(model.preset, "model.preset"))
            .sgbm_block_size;
  } catch (const InputError&) {
    return std::nullopt;
  }
  return view;
}

}  // namespace

VisitSurface visit_surface(storage::ProjectStore& store, storage::RecordId visit_id,
                           const PoleMask& mask) {
  VisitSurface out;
  std::vector<Eigen::Vector3d> targets;
  bool every_sigma_known = true, every_pair_known = true;
  double sigma = 0;
  for (const auto& summary : store.list_visit_models(visit_id)) {
    storage::Model model = store.load_model(summary.id);
    const storage::ModelRegistration reg = storage::read_model_registration(model.registration);
    if (reg.is_scaled() && reg.predicted_depth_sigma_mm && *reg.predicted_depth_sigma_mm > 0)
      sigma = std::max(sigma, *reg.predicted_depth_sigma_mm / 1000);
    else
      every_sigma_known = false;
    const auto pair = reg.is_scaled() ? stereo_pair_of(model) : std::nullopt;
    if (pair)
      out.precision.pairs.push_back(*pair);
    else
      every_pair_known = false;
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
  if (!every_pair_known) out.precision.pairs.clear();
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
