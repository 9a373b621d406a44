#include "firmware-app/field_records.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

namespace rockface::app {

namespace {

storage::Mesh project_mesh(const photogrammetry::SurfaceMesh& m) {
  storage::Mesh out;
  out.vertices = m.vertices;
  out.faces.reserve(m.triangles.size());
  for (const auto& t : m.triangles) out.faces.push_back({t[0], t[1], t[2]});
  out.texcoords.reserve(m.texcoords.size());
  for (const auto& t : m.texcoords) out.texcoords.push_back({t.x(), t.y()});
  out.colours = m.colours;
  return out;
}

nlohmann::json vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace

storage::Model model_record(const photogrammetry::ReconstructionResult& rec,
                            storage::RecordId capture_id, const std::string& preset) {
  storage::Model model;
  model.capture_id = capture_id;
  model.preset = preset;
  model.mesh = project_mesh(rec.mesh);
  model.texture_capture_id = capture_id;
  model.texture_side = "left";
  storage::Registration& r = model.registration;
  r.kind = rec.scale_source == "range pole" ? "range_pole_compass" : rec.scale_source;
  r.scale = rec.model_to_world.scale;
  const Eigen::Quaterniond q(rec.model_to_world.R);
  r.rotation_wxyz = {q.w(), q.x(), q.y(), q.z()};
  r.translation = rec.model_to_world.t;
  nlohmann::json p = {{"scale", rec.scale_source},
                      {"vertical", rec.vertical_source},
                      {"north", rec.north_source},
                      {"predicted_depth_sigma_mm", rec.accuracy.sigma_z * 1000},
                      {"point_spacing_mm", rec.point_spacing * 1000}};
  if (rec.north_rotation_deg) p["north_rotation_deg"] = *rec.north_rotation_deg;
  if (rec.targets) {
    p["targets"] = nlohmann::json::array();
    for (const auto& t : rec.targets->model)
      p["targets"].push_back(vec(rec.model_to_world.apply(t)));
  }
  for (const auto& c : rec.scale_checks) p["scale_check " + c.source] = c.ratio;
  if (rec.control_points) {
    r.rms_m = rec.control_points->rms_m;
    for (const auto& res : rec.control_points->residuals)
      model.residuals.push_back({res.id, res.residual});
  }
  r.parameters_json = p.dump();
  return model;
}

storage::AnalysisRun analysis_record(const storage::Report& report, storage::RecordId visit_id,
                                     std::optional<storage::RecordId> model_id,
                                     const std::string& preset) {
  storage::AnalysisRun run;
  run.visit_id = visit_id;
  run.model_id = model_id;
  run.preset = preset;
  run.effects = report.effects_simulated;
  for (const auto& b : report.blocks) {
    storage::BlockResult r;
    r.label = b.id;
    r.source = b.source;
    r.code = b.code;
    r.volume_m3 = b.volume.value_or(0);
    r.finite = b.finite;
    r.removable = b.removable;
    r.marginal = b.marginal;
    r.mode = b.mode ? b.mode->type : "none";
    r.fos = b.fos;
    r.report_json = storage::block_to_json(b);
    run.blocks.push_back(std::move(r));
  }
  return run;
}

}  // namespace rockface::app
