#include "storage/report/reconstruction_report.h"

#include <nlohmann/json.hpp>

namespace rockface::storage {

namespace {

nlohmann::json json_vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}
nlohmann::json json_vec(const Eigen::Vector2d& v) {
  return {v.x(), v.y()};
}

}  // namespace

std::string reconstruction_report_json(const photogrammetry::ReconstructionResult& r,
                                       const ReconstructionReportContext& c) {
  using nlohmann::json;
  const auto& ro = r.orientation;
  json j;
  j["format"] = "rockface-reconstruction/1";
  j["preset"] = c.preset;
  j["images"] = {{"left", c.left_image}, {"right", c.right_image}};
  j["units"] = r.scaled ? "m" : "base";  // unscaled models are in units of the base
  j["points"] = r.mesh.size();
  j["triangles"] = r.mesh.triangles.size();
  j["point_spacing"] = r.point_spacing;
  j["distance"] = r.distance;
  j["base"] = r.base;
  j["base_to_distance"] = r.accuracy.base_ratio;
  j["sigma_z"] = r.accuracy.sigma_z;
  j["sigma_z_formula"] = "Z^2 sigma_d / (B f)";
  j["focal_px"] = r.focal_px;
  j["disparity_sigma_px"] = r.disparity_sigma_px;
  j["dense"] = {{"image_scale", r.dense_scale},
                {"min_disparity", r.disparity_range.min_disparity},
                {"num_disparities", r.disparity_range.num_disparities},
                {"valid_fraction", r.dense_valid_fraction},
                {"left_right_rejected_fraction", r.lr_rejected_fraction},
                // How differently the two photographs light the same rock
                // (view_shading.h), and whether matching was normalised for it.
                {"shading",
                 {{"tie_points", r.view_shading.samples},
                  {"gain", r.view_shading.gain},
                  {"spread", r.view_shading.spread},
                  {"normalised", r.shading_normalised}}}};
  json R = json::array();
  for (int i = 0; i < 3; ++i) R.push_back({ro.R(i, 0), ro.R(i, 1), ro.R(i, 2)});
  j["orientation"] = {{"matches", ro.matches},
                      {"inliers", ro.inliers},
                      {"tie_points_area_matched", r.tie_points.refined},
                      {"tie_points_rejected_by_area_matching", r.tie_points.rejected},
                      {"rms_reprojection_px", ro.rms_reprojection_px},
                      {"median_reprojection_px", ro.median_reprojection_px},
                      {"rotation_sigma_deg", ro.rotation_sigma_deg},
                      {"base_direction_sigma_deg", ro.direction_sigma_deg},
                      {"median_intersection_angle_deg", ro.median_intersection_deg},
                      {"tie_point_coverage", ro.overlap_fraction},
                      {"R", R},
                      {"t", json_vec(ro.t)}};
  json reg;
  reg["scaled"] = r.scaled;
  reg["scale_source"] = r.scale_source;
  reg["vertical_source"] = r.vertical_source;
  reg["north_source"] = r.north_source;
  reg["scale"] = r.model_to_world.scale;
  reg["datum"] = json_vec(r.datum);
  if (r.targets) {
    json targets = json::array();
    const char* names[2] = {"lower", "upper"};
    for (int k = 0; k < 2; ++k)
      targets.push_back(
          {{"which", names[k]},
           {"left_px", json_vec(r.targets->left[k].centre_px)},
           {"right_px", json_vec(r.targets->right[k].centre_px)},
           {"left_ellipse_centre_px", json_vec(r.targets->left[k].ellipse_centre)},
           {"diameter_px",
            std::min(r.targets->left[k].diameter_px, r.targets->right[k].diameter_px)},
           {"world",
            json_vec(Eigen::Vector3d(r.model_to_world.apply(r.targets->model[k]) + r.datum))}});
    reg["range_pole"] = {{"length_m", c.range_pole_m.value_or(0.0)}, {"targets", targets}};
  }
  if (c.north)
    reg["north"] = {{"azimuth_deg", c.north->azimuth_deg},
                    {"declination_deg", c.north->declination_deg},
                    {"reference_line_px", {json_vec(c.north->from_px), json_vec(c.north->to_px)}},
                    {"rotation_about_vertical_deg", r.north_rotation_deg.value_or(0.0)}};
  if (c.baseline_m) reg["baseline_m"] = *c.baseline_m;
  if (r.control_points) {
    json res = json::array();
    for (const auto& p : r.control_points->residuals)
      res.push_back({{"id", p.id},
                     {"residual_m", json_vec(p.residual)},
                     {"distance_m", p.distance},
                     {"on_target", p.on_target}});
    reg["control_points"] = {{"rms_m", r.control_points->rms_m},
                             {"worst", r.control_points->worst_id},
                             {"worst_m", r.control_points->worst_m},
                             {"residuals", res}};
  }
  json checks = json::array();
  for (const auto& s : r.scale_checks) checks.push_back({{"source", s.source}, {"ratio", s.ratio}});
  reg["scale_checks"] = checks;
  j["registration"] = reg;
  j["warnings"] = r.accuracy.warnings;
  return j.dump(2) + "\n";
}

std::string face_registration_json(const photogrammetry::FaceRegistration& face) {
  using nlohmann::json;
  json images = json::array();
  for (const auto& r : face.images) {
    json i = {{"name", r.name}, {"scale", r.to_face.scale}};
    if (r.reference < 0) {
      i["role"] = "master";
    } else {
      i["role"] = "registered";
      i["reference"] = face.images[r.reference].name;
      i["tie_points"] = r.tie_points;
      i["tie_point_rms_m"] = r.tie_rms_m;
      i["overlap"] = r.overlap;
      i["surface_rms_m"] = r.surface_rms_m;
      i["surface_rms_before_icp_m"] = r.surface_rms_before_icp_m;
    }
    images.push_back(i);
  }
  json j = {{"format", "rockface-face-registration/1"}, {"images", images}};
  if (face.control_points) {
    json res = json::array();
    for (const auto& p : face.control_points->residuals)
      res.push_back(
          {{"id", p.id}, {"residual_m", json_vec(p.residual)}, {"distance_m", p.distance}});
    j["control_points"] = {{"rms_m", face.control_points->rms_m},
                           {"worst", face.control_points->worst_id},
                           {"worst_m", face.control_points->worst_m},
                           {"residuals", res}};
    j["datum"] = json_vec(face.datum);
  }
  return j.dump(2) + "\n";
}

}  // namespace rockface::storage
