#include "firmware-app/records/field_records.h"

#include <nlohmann/json.hpp>

#include "firmware-app/records/project_mesh.h"
#include "storage/project/model_registration.h"

namespace rockface::app {

namespace {

nlohmann::json record_vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace

storage::Model model_record(const photogrammetry::ReconstructionResult& rec,
                            storage::RecordId capture_id,
                            const storage::ReconstructionReportContext& accuracy) {
  storage::Model model;
  model.capture_id = capture_id;
  model.preset = accuracy.preset;
  model.mesh = project_mesh(rec.mesh);
  model.texture_capture_id = capture_id;
  model.texture_side = "left";
  storage::Registration& r = model.registration;
  // What scaled and oriented it, no more (issue 42): a pole without a
  // compass line gives scale and vertical, not north.
  r.kind = storage::registration_kind(rec.scale_source, rec.north_source);
  storage::set_similarity(r, rec.model_to_world);
  // The whole reconstruction report (what the field report prints), plus the
  // two figures the tablet reads without walking it: the targets in the
  // project frame and the predicted depth precision of a picked point.
  nlohmann::json p = nlohmann::json::parse(storage::reconstruction_report_json(rec, accuracy));
  p["predicted_depth_sigma_mm"] = rec.accuracy.sigma_z * 1000;
  if (rec.targets) {
    p["targets"] = nlohmann::json::array();
    for (const auto& t : rec.targets->model)
      p["targets"].push_back(record_vec(rec.model_to_world.apply(t)));
  }
  if (rec.control_points) {
    r.rms_m = rec.control_points->rms_m;
    for (const auto& res : rec.control_points->residuals)
      model.residuals.push_back({res.id, res.residual});
  }
  r.parameters_json = p.dump();
  return model;
}

storage::AnalysisRun analysis_record(const analysis::Report& report, storage::RecordId visit_id,
                                     std::optional<storage::RecordId> model_id, Preset preset) {
  storage::AnalysisRun run;
  run.visit_id = visit_id;
  run.model_id = model_id;
  run.preset = preset_name(preset);
  run.effects = report.effects_simulated;
  run.blocks = report.blocks;
  return run;
}

}  // namespace rockface::app
