#include "storage/project/model_registration.h"

#include <nlohmann/json.hpp>

namespace rockface::storage {

namespace {

using nlohmann::json;

const json* param_member(const json& j, const char* key) {
  if (!j.is_object()) return nullptr;
  const auto it = j.find(key);
  return it == j.end() ? nullptr : &*it;
}

std::optional<double> param_number(const json& j, const char* key) {
  const json* v = param_member(j, key);
  if (!v || !v->is_number()) return std::nullopt;
  return v->get<double>();
}

std::string param_text(const json& j, const char* key) {
  const json* v = param_member(j, key);
  return v && v->is_string() ? v->get<std::string>() : std::string();
}

std::optional<Eigen::Vector3d> stored_vector3(const json& j) {
  if (!j.is_array() || j.size() != 3) return std::nullopt;
  for (const auto& x : j)
    if (!x.is_number()) return std::nullopt;
  return Eigen::Vector3d(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

std::optional<Eigen::Vector2d> param_pixel(const json* j) {
  if (!j || !j->is_array() || j->size() != 2 || !(*j)[0].is_number() || !(*j)[1].is_number())
    return std::nullopt;
  return Eigen::Vector2d((*j)[0].get<double>(), (*j)[1].get<double>());
}

void read_control_points(const json& cp, ModelRegistration& out) {
  if (!cp.is_object()) return;
  out.has_control_points = true;
  out.control_rms_m = param_number(cp, "rms_m");
  out.worst_control = param_text(cp, "worst");
  out.worst_control_m = param_number(cp, "worst_m");
  out.control_points.clear();
  if (const json* res = param_member(cp, "residuals"); res && res->is_array())
    for (const auto& p : *res)
      out.control_points.push_back(
          {param_text(p, "id"), param_number(p, "distance_m").value_or(0.0)});
}

void read_pole(const json& pole, ModelRegistration& out) {
  if (!pole.is_object()) return;
  out.has_pole = true;
  out.pole_length_m = param_number(pole, "length_m");
  if (const json* targets = param_member(pole, "targets"); targets && targets->is_array())
    for (const auto& t : *targets) {
      const auto px = param_pixel(param_member(t, "left_px"));
      if (!px) continue;
      out.pole_targets.push_back({param_text(t, "which"), *px, param_number(t, "diameter_px")});
    }
}

void read_sources(const json& reg, ModelRegistration& out) {
  if (!reg.is_object()) return;
  out.scale_source = param_text(reg, "scale_source");
  out.vertical_source = param_text(reg, "vertical_source");
  out.north_source = param_text(reg, "north_source");
  if (const json* s = param_member(reg, "scaled"); s && s->is_boolean())
    out.scaled = s->get<bool>();
  out.scale = param_number(reg, "scale");
  if (const json* pole = param_member(reg, "range_pole")) read_pole(*pole, out);
  if (const json* n = param_member(reg, "north"); n && n->is_object()) {
    out.has_north = true;
    out.compass_azimuth_deg = param_number(*n, "azimuth_deg");
    out.declination_deg = param_number(*n, "declination_deg");
    out.north_rotation_deg = param_number(*n, "rotation_about_vertical_deg");
  }
  if (const json* cp = param_member(reg, "control_points")) read_control_points(*cp, out);
}

void read_reconstruction(const json& p, ModelRegistration& out) {
  out.record = ModelRegistration::Record::reconstruction;
  out.predicted_depth_sigma_mm = param_number(p, "predicted_depth_sigma_mm");
  out.sigma_z_m = param_number(p, "sigma_z");
  out.distance_m = param_number(p, "distance");
  out.base_m = param_number(p, "base");
  out.base_to_distance = param_number(p, "base_to_distance");
  out.point_spacing_m = param_number(p, "point_spacing");
  if (const json* o = param_member(p, "orientation")) {
    out.inliers = param_number(*o, "inliers");
    out.matches = param_number(*o, "matches");
    out.rms_reprojection_px = param_number(*o, "rms_reprojection_px");
    out.tie_point_coverage = param_number(*o, "tie_point_coverage");
  }
  if (const json* d = param_member(p, "dense")) {
    out.dense_valid_fraction = param_number(*d, "valid_fraction");
    out.dense_image_scale = param_number(*d, "image_scale");
  }
  if (const json* reg = param_member(p, "registration")) read_sources(*reg, out);
  if (const json* targets = param_member(p, "targets"); targets && targets->is_array())
    for (const auto& t : *targets)
      if (const auto v = stored_vector3(t)) out.targets_project.push_back(*v);
  if (const json* i = param_member(p, "import"); i && i->is_object())
    out.imported_from = param_text(*i, "words");
  if (const json* w = param_member(p, "warnings"); w && w->is_array())
    for (const auto& x : *w)
      if (x.is_string()) out.warnings.push_back(x.get<std::string>());
}

void read_face_images(const json& p, ModelRegistration& out) {
  out.record = ModelRegistration::Record::face_images;
  out.predicted_depth_sigma_mm = param_number(p, "predicted_depth_sigma_mm");
  if (const json* images = param_member(p, "images"); images && images->is_array())
    for (const auto& i : *images) {
      RegisteredImage r;
      r.name = param_text(i, "name");
      r.role = param_text(i, "role");
      r.reference = param_text(i, "reference");
      r.tie_points = param_number(i, "tie_points");
      r.tie_point_rms_m = param_number(i, "tie_point_rms_m");
      r.overlap = param_number(i, "overlap");
      r.surface_rms_m = param_number(i, "surface_rms_m");
      r.scale = param_number(i, "scale").value_or(1.0);
      out.images.push_back(r);
    }
  if (const json* cp = param_member(p, "control_points")) read_control_points(*cp, out);
}

}  // namespace

bool ModelRegistration::oriented() const {
  if (!north_source.empty()) return north_source != "none";
  // A record that does not say: control points and a further pair on pair 1
  // bring north; the pole alone and nothing at all do not.
  return kind != "none" && kind != "range_pole";
}

ModelRegistration read_model_registration(const Registration& r) {
  ModelRegistration out;
  const json p = json::parse(r.parameters_json.empty() ? "{}" : r.parameters_json, nullptr, false);
  if (p.is_object()) {
    out.has_format = param_member(p, "format") != nullptr;
    if (r.kind == "face_images" || param_text(p, "format") == "rockface-face-registration/1")
      read_face_images(p, out);
    else if (!p.empty())
      read_reconstruction(p, out);
  }
  out.kind = honest_registration_kind(r.kind, out.north_source);
  return out;
}

std::string registration_kind(const std::string& scale_source, const std::string& north_source) {
  if (scale_source == "range pole")
    return north_source == "compass" ? "range_pole_compass" : "range_pole";
  if (scale_source == "control points") return "ground_control";
  if (scale_source.empty()) return "none";
  return scale_source;  // "baseline" | "none"
}

std::string honest_registration_kind(const std::string& stored_kind,
                                     const std::string& north_source) {
  if (stored_kind == "range_pole_compass" && north_source == "none") return "range_pole";
  if (stored_kind == "control points") return "ground_control";
  return stored_kind;
}

}  // namespace rockface::storage
