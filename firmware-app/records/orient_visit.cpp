#include "firmware-app/records/orient_visit.h"

#include <cmath>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/analysis/preset_options.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/photogrammetry/estimators/registration.h"
#include "firmware-app/records/project_mesh.h"
#include "storage/project/model_registration.h"

namespace rockface::app {

namespace {

using nlohmann::json;

// The photograph's size the texture coordinates are fractions of.
std::pair<int, int> left_photo_size(storage::ProjectStore& store, const storage::Model& m,
                                    const std::string& where) {
  if (m.texture_capture_id) {
    const auto captures = store.list_captures();
    for (const auto& c : captures)
      if (c.id == *m.texture_capture_id && c.calibration_id) {
        const auto k = store.load_calibration(*c.calibration_id).intrinsics;
        if (k.width > 0 && k.height > 0) return {k.width, k.height};
      }
  }
  throw InputError(where, "its 3D image has no calibrated photograph to take the line's pixels in");
}

Eigen::Vector3d on_surface(const photogrammetry::SurfaceMesh& mesh, const Eigen::Vector2d& px,
                           double radius, const std::string& where) {
  const auto p = mesh.point_at_pixel(px, radius);
  if (!p) {
    throw InputError(where, "no 3D image at pixel (" + format_fixed(px.x(), 1) + ", " +
                                format_fixed(px.y(), 1) +
                                ") of the left photograph: tap the line's ends on rock");
  }
  return *p;
}

json turned_vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

// The stored report made to say what now orients the model.
std::string with_north(const std::string& parameters, const photogrammetry::Similarity& north,
                       const photogrammetry::NorthReference& line, double total_deg) {
  json p = json::parse(parameters.empty() ? "{}" : parameters, nullptr, false);
  if (!p.is_object()) return parameters;
  if (p.contains("targets") && p["targets"].is_array())
    for (auto& t : p["targets"])
      if (t.is_array() && t.size() == 3)
        t = turned_vec(north.apply({t[0].get<double>(), t[1].get<double>(), t[2].get<double>()}));
  if (p.contains("registration") && p["registration"].is_object()) {
    json& r = p["registration"];
    r["north_source"] = "compass";
    r["north"] = {{"azimuth_deg", line.azimuth_deg},
                  {"declination_deg", line.declination_deg},
                  {"reference_line_px",
                   {{line.from_px.x(), line.from_px.y()}, {line.to_px.x(), line.to_px.y()}}},
                  {"rotation_about_vertical_deg", total_deg},
                  {"given", "after the reconstruction"}};
  }
  if (p.contains("warnings") && p["warnings"].is_array()) {
    json kept = json::array();
    for (const auto& w : p["warnings"])
      if (!w.is_string() || w.get<std::string>().rfind("no north source", 0) != 0)
        kept.push_back(w);
    p["warnings"] = kept;
  }
  return p.dump();
}

}  // namespace

VisitOrientation orient_visit_by_compass(storage::ProjectStore& store, storage::RecordId visit_id,
                                         const photogrammetry::NorthReference& north) {
  const std::string where = "visit " + std::to_string(visit_id);
  const auto models = store.list_visit_models(visit_id);
  if (models.empty())
    throw InputError(where, "has no 3D image: reconstruct its photographs before orienting it");
  if (const auto m = store.list_measurements(visit_id); !m.empty())
    throw InputError(where, "already has " + std::to_string(m.size()) +
                                " measurements in its present frame: give the compass line "
                                "before mapping on it");
  if (store.load_visit_placement(visit_id))
    throw InputError(where,
                     "is placed in the tunnel already: give the compass line before "
                     "placing it");
  const storage::Model first = store.load_model(models.front().id);
  const storage::ModelRegistration reg = storage::read_model_registration(first.registration);
  if (reg.kind == "ground_control")
    throw InputError(where, "has its north from its control points");
  if (!reg.is_scaled() && reg.kind == "none")
    throw InputError(where,
                     "is neither scaled nor levelled (no range pole): north about a "
                     "vertical it does not have would mean nothing");

  const auto [width, height] = left_photo_size(store, first, where);
  storage::Mesh copy = first.mesh;
  const photogrammetry::SurfaceMesh mesh = surface_mesh(std::move(copy), width, height);
  // As the reconstruction picks the line (two lattice steps of its dense
  // matching, in full-size pixels).
  const double lattice = analysis::preset_options(parse_preset(first.preset, where + " preset"))
                             .reconstruction.lattice_step;
  const double radius = 2.0 * lattice / reg.dense_image_scale.value_or(1.0);
  const Eigen::Vector3d a = on_surface(mesh, north.from_px, radius, north.where + " first point");
  const Eigen::Vector3d b = on_surface(mesh, north.to_px, radius, north.where + " second point");
  const Eigen::Vector3d pivot = reg.targets_project.empty() ? a : reg.targets_project.front();
  photogrammetry::Similarity turn;
  try {
    turn = photogrammetry::north_rotation(a, b, north.azimuth_deg, north.declination_deg, pivot);
  } catch (const InputError& e) {
    throw InputError(north.where, e.reason());
  }
  VisitOrientation out;
  out.turned_deg = rad_to_deg(Eigen::AngleAxisd(turn.R).angle()) *
                   (Eigen::AngleAxisd(turn.R).axis().z() < 0 ? -1 : 1);
  const double total = reg.north_rotation_deg.value_or(0.0) + out.turned_deg;

  for (const auto& summary : models) {
    storage::Model m = store.load_model(summary.id);
    for (auto& v : m.mesh.vertices) v = turn.apply(v);
    storage::set_similarity(m.registration, storage::similarity_of(m.registration).then(turn));
    if (m.camera_to_mesh) m.camera_to_mesh = m.camera_to_mesh->then(turn);
    const storage::ModelRegistration r = storage::read_model_registration(m.registration);
    m.registration.parameters_json = with_north(m.registration.parameters_json, turn, north, total);
    if (r.record == storage::ModelRegistration::Record::reconstruction)
      m.registration.kind = storage::registration_kind(r.scale_source, "compass");
    for (auto& res : m.residuals) res.residual = turn.R * res.residual;
    m.id = 0;
    m.created_at.clear();
    store.save_model(m);
  }
  out.note = "north from the compass line at " + format_zero_padded(north.azimuth_deg, 5, 1, "°") +
             ", turned by " + format_fixed(out.turned_deg, 2, "°");
  return out;
}

}  // namespace rockface::app
