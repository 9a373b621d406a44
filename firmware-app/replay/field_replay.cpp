#include "firmware-app/replay/field_replay.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "camera/capture_guidance.h"
#include "camera/mock_camera.h"
#include "camera/synthetic_renderer.h"
#include "core/analysis/scene_analysis.h"
#include "core/common/error.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/measure/pair_photo.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "firmware-app/analysis/scene_input.h"
#include "firmware-app/measure/measure_records.h"
#include "firmware-app/records/field_records.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
#include "firmware-app/replay/replay_capture.h"
#include "firmware-app/replay/replay_more_pairs.h"
#include "firmware-app/replay/replay_picks.h"
#include "firmware-app/tunnel/replay_tunnel.h"
#include "storage/project/project_store.h"
#include "storage/report/reconstruction_report.h"
#include "storage/scene/camera_json.h"
#include "storage/scene/scene.h"

namespace rockface::app {

namespace {

namespace fs = std::filesystem;

// Compass bearing (degrees clockwise from north) of the horizontal
// projection of a line, and its end points in the left image.
std::optional<photogrammetry::NorthReference> compass_reading(
    const camera::SyntheticScene& scene, const photogrammetry::CameraIntrinsics& k,
    const std::string& source) {
  if (!scene.reference_line) return std::nullopt;
  const auto& [from, to] = *scene.reference_line;
  const photogrammetry::CameraPose pose =
      camera::station_pose(scene.stations[0], "imaging.stations[0]");
  std::vector<cv::Point3d> world{{from.x(), from.y(), from.z()}, {to.x(), to.y(), to.z()}};
  cv::Mat R(3, 3, CV_64F), rvec, tvec;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R.at<double>(i, j) = pose.R(i, j);
  cv::Rodrigues(R, rvec);
  const Eigen::Vector3d t = pose.translation();
  tvec = (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
  const cv::Mat K = (cv::Mat_<double>(3, 3) << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
  const cv::Mat dist(1, 5, CV_64F, const_cast<double*>(k.distortion.data()));
  std::vector<cv::Point2d> px;
  cv::projectPoints(world, rvec, tvec, K, dist, px);
  photogrammetry::NorthReference north;
  north.from_px = {px[0].x, px[0].y};
  north.to_px = {px[1].x, px[1].y};
  north.azimuth_deg = rad_to_deg(std::atan2(to.x() - from.x(), to.y() - from.y()));
  if (north.azimuth_deg < 0) north.azimuth_deg += 360;
  // The scene's field, not the option of `reconstruct` (issue 41).
  north.where = source + ": imaging.reference_line";
  return north;
}

// Each scene joint that has picked traces: its measured plane beside the
// scene's.
std::vector<JointComparison> joint_comparisons(const storage::Scene& scene,
                                               const measure::MeasuredPicks& measured) {
  std::vector<JointComparison> out;
  for (const auto& j : scene.joints)
    for (const auto& m : measured.joints) {
      if (m.label != j.id) continue;
      JointComparison c;
      c.id = j.id;
      c.scene_dip = j.dip;
      c.scene_dipdir = j.dipdir;
      c.traces = m.traces;
      c.measured = m.plane.known;
      c.problem = m.plane.problem;
      for (const auto& t : measured.traces)
        if (t.joint == j.id && t.compass) c.compass_read.push_back(t.m.id);
      if (c.measured) {
        c.dip = rad_to_deg(m.plane.orientation.dip);
        c.dipdir = rad_to_deg(m.plane.orientation.dipdir);
        c.sigma = rad_to_deg(m.plane.sigma);
        const double cosine = std::abs(geometry::plane_normal_deg(c.dip, c.dipdir)
                                           .dot(geometry::plane_normal_deg(j.dip, j.dipdir)));
        c.angle = rad_to_deg(std::acos(std::min(1.0, cosine)));
      }
      out.push_back(std::move(c));
    }
  return out;
}

}  // namespace

ReplayOutcome replay_field_workflow(const ReplayRequest& request, Progress& progress) {
  ReplayOutcome out;
  const bool from_scene = fs::is_regular_file(request.source);
  if (!from_scene && !fs::is_directory(request.source))
    throw InputError(request.source, "neither a scene file nor a folder of captures");

  std::optional<storage::Scene> scene;
  std::optional<SyntheticSceneInput> synthetic;
  std::optional<Eigen::Vector3d> typed_pole;
  std::unique_ptr<camera::MockCamera> cam;
  photogrammetry::CameraIntrinsics intrinsics;
  photogrammetry::RegistrationSources sources;
  const fs::path spool = fs::path(request.project).parent_path() /
                         (fs::path(request.project).filename().string() + ".spool");
  if (from_scene) {
    scene = storage::load_scene(request.source);
    synthetic = synthetic_scene_from_scene(*scene);
    // A pick naming a pair the scene does not photograph, or a pixel outside
    // the photographs: bad input before anything is captured or stored.
    check_picks_before_capture(*scene, std::max<std::size_t>(1, synthetic->pairs.size()));
    // A typed placement off the alignment: refused before the camera
    // spools a shot or the project is created (issue 41).
    typed_pole = typed_range_pole(*scene);
    cam = camera::MockCamera::synthetic(synthetic->scene, spool.string());
    intrinsics = camera::rendered_intrinsics(synthetic->scene);
    intrinsics.body = "rockface synthetic camera";
    if (synthetic->scene.range_pole) sources.range_pole_m = synthetic->scene.range_pole->length;
    sources.north = compass_reading(synthetic->scene, intrinsics, scene->source);
  } else {
    const fs::path cam_file = fs::path(request.source) / "camera.json";
    if (!fs::exists(cam_file))
      throw InputError(cam_file.string(),
                       "a capture folder needs the calibration of its camera (camera.json)");
    intrinsics = storage::load_camera_json(cam_file.string());
    cam = camera::MockCamera::replay(request.source, spool.string());
  }
  // --preset, else the scene's analysis.preset; a capture folder has no
  // scene, so its default is the scene's default (standard).
  const Preset chosen = request.preset.value_or(scene ? scene->analysis.preset : Preset::standard);
  const photogrammetry::ReconstructionPreset preset = photogrammetry::reconstruction_preset(chosen);

  // Capture the pair: focus locked after the first shot, optics checked.
  progress.step("capture", 0.0);
  cam->lock_focus();
  const camera::Capture left = cam->capture();
  const camera::Capture right = cam->capture();
  camera::require_same_optics(left.exif, right.exif);
  for (const auto& note : camera::check_pair(left.exif, right.exif))
    out.guidance.push_back(note.text);

  storage::ProjectInfo info;
  info.name =
      scene && !scene->name.empty() ? scene->name : fs::path(request.source).filename().string();
  if (scene) info.datum = scene->datum;
  storage::ProjectStore store = storage::ProjectStore::open_or_create(request.project, info);
  if (store.read_only())
    throw InputError(request.project, "cannot replay into it: " + store.read_only_reason());
  out.visit_id = store.begin_visit("replay " + request.source);

  storage::CameraBody body;
  body.make = left.exif.make.empty() ? "unknown" : left.exif.make;
  body.model = left.exif.model.empty() ? cam->model() : left.exif.model;
  storage::Calibration calibration;
  calibration.body_id = store.save_camera_body(body);
  calibration.intrinsics = intrinsics;
  calibration.focal_setting_mm = left.exif.focal_length_mm.value_or(0);
  calibration.method =
      from_scene ? "synthetic (rendering camera)" : "camera.json of " + request.source;
  const storage::RecordId calibration_id = store.save_calibration(calibration);

  storage::Capture capture;
  capture.visit_id = out.visit_id;
  capture.calibration_id = calibration_id;
  capture.label = "replay pair";
  capture.left.bytes = left.image.data;
  capture.right.bytes = right.image.data;
  capture.left_exif = camera::exif_fields(left.exif);
  capture.right_exif = camera::exif_fields(right.exif);
  capture.settings["preset"] = preset.name;
  out.capture_id = store.save_capture(capture);

  // Reconstruct and register.
  const cv::Mat left_image = decode_shot(left.image, "left");
  const cv::Mat right_image = decode_shot(right.image, "right");
  photogrammetry::ReconstructionResult rec = photogrammetry::reconstruct(
      left_image, right_image, intrinsics, intrinsics, preset, sources, progress);
  // The registered frame has its origin at the pole (heading turned about
  // the reference line); the scene surveys where the pole stood, so the
  // model moves into the project frame (datum-relative) of the traces and joints.
  // In a tunnel the geologist may type where the pole stood (chainage,
  // offset, height) instead of surveying it.
  if (synthetic && synthetic->scene.range_pole && rec.targets) {
    const Eigen::Vector3d pole = typed_pole.value_or(synthetic->scene.range_pole->base);
    const Eigen::Vector3d shift = pole - rec.model_to_world.apply(rec.targets->model[0]);
    rec.mesh.transform(1.0, Eigen::Matrix3d::Identity(), shift);
    rec.model_to_world.t += shift;
  }
  const storage::Model model =
      model_record(rec, out.capture_id,
                   {left.image.saved_path, right.image.saved_path, preset.name,
                    sources.range_pole_m, sources.baseline_m, sources.north});
  out.model_id = store.save_model(model);
  std::optional<MorePairsOutcome> more;
  if (synthetic && synthetic->pairs.size() > 1) {
    more = replay_more_pairs(
        store, {out.visit_id, calibration_id, &*synthetic, intrinsics, preset.name, preset, spool},
        left_image, rec, progress);
    out.more_model_ids = more->model_ids;
    for (const auto& r : more->face.images)
      if (r.reference >= 0)
        out.guidance.push_back(r.name + " registered to " + more->face.images[r.reference].name +
                               ": " + std::to_string(r.tie_points) + " tie points, surface rms " +
                               std::to_string(r.surface_rms_m * 1000) + " mm");
  }
  out.model_points = rec.mesh.size();
  out.registration = "scale: " + rec.scale_source + ", vertical: " + rec.vertical_source +
                     ", north: " + rec.north_source;
  out.predicted_depth_sigma_m = rec.accuracy.sigma_z;
  for (const auto& w : rec.accuracy.warnings) out.guidance.push_back(w);

  if (!scene) return out;  // a capture folder has no traces to analyse
  if (scene->tunnel) out.guidance.push_back(place_replayed_visit(store, *scene, out.visit_id));

  // Traces: measured on the reconstructed image where the scene gives picks
  // (replay_picks.h); else those of the scene, or the synthetic scene's true
  // traces (what the geologist would mark on the model).
  std::optional<ReplayPicks> picked;
  if (scene->picks) {
    progress.step("measure", 0.75);
    picked = measure_replay_picks(*scene, rec, intrinsics, preset, left_image, right_image,
                                  more ? &*more : nullptr);
    for (const auto& note : picked->notes) out.guidance.push_back(note);
    out.joints = joint_comparisons(*scene, picked->measured);
  }
  // The analysis input, filled once from the scene and then with what was
  // measured: the measured traces and joint planes.
  analysis::AnalysisInput analysed = analysis_input(*scene);
  if (picked) {
    analysed.traces = picked->traces;
    analysed.joints = picked->joints;
  }
  if (analysed.traces.empty()) {
    int n = 0;
    for (const auto& seg : camera::true_trace_segments(synthetic->scene)) {
      // A rendered tunnel's walls are thousands of facets: the geologist maps
      // the face, so only the face's traces are taken.
      if (scene->tunnel && scene->tunnel->render && seg.patch.rfind("FACE", 0) != 0) continue;
      analysed.traces.push_back(
          {"T" + std::to_string(++n),
           seg.joint,
           {seg.world[0] + synthetic->origin, seg.world[1] + synthetic->origin}});
    }
  }
  if (analysed.patches.empty() && scene->tunnel && scene->tunnel->render) {
    // A rendered tunnel's free surface is its face.
    for (const auto& p : synthetic->scene.patches)
      if (p.id.rfind("FACE", 0) == 0) {
        analysed.patches.push_back({p.id, {}});
        for (const auto& x : p.polygon)
          analysed.patches.back().polygon.push_back(x + synthetic->origin);
      }
  }
  if (analysed.patches.empty())
    throw InputError(request.source, "surface.patches: the scene has no free surface");
  // The traces, and the free surface as areas: with the joints below, the
  // visit holds all the analysis needs, so it can be analysed again from
  // the project alone (the tablet UI does).
  std::vector<storage::Measurement> measurements;
  auto measured = [&](storage::Measurement::Kind kind, const std::string& label,
                      const std::vector<Eigen::Vector3d>& absolute) {
    storage::Measurement m;
    m.visit_id = out.visit_id;
    m.model_id = out.model_id;
    m.kind = kind;
    m.label = label;
    for (const auto& p : absolute) m.points.push_back(p - scene->datum);
    return m;
  };
  if (picked) {
    // Each measurement with its own pair's model and capture.
    std::map<std::string, PairRecords> further;
    if (more)
      for (std::size_t k = 0; k < more->model_ids.size(); ++k)
        further[measure::pair_photo(static_cast<int>(k) + 2, "left")] = {more->model_ids[k],
                                                                         more->capture_ids[k]};
    measurements = measurement_records(picked->measured, out.visit_id,
                                       {out.model_id, out.capture_id}, further);
    join_trace_records(picked->joined, measurements);
  } else
    for (const auto& t : analysed.traces) {
      measurements.push_back(measured(storage::Measurement::Kind::trace, t.id, t.points));
      measurements.back().joint_label = t.joint.value_or("");
    }
  for (const auto& patch : analysed.patches)
    measurements.push_back(measured(storage::Measurement::Kind::area, patch.id, patch.polygon));
  store.save_measurements(out.visit_id, measurements);
  std::vector<storage::Joint> joints;
  for (const auto& j : analysed.joints) {
    storage::Joint joint;
    joint.visit_id = out.visit_id;
    joint.label = j.id;
    joint.dip_deg = j.dip;
    joint.dipdir_deg = j.dipdir;
    if (j.point) joint.point = *j.point - scene->datum;
    joint.friction_deg = j.friction;
    joint.cohesion_pa = j.cohesion;
    joint.source = "scene";
    if (picked)
      for (const auto& m : picked->measured.joints)
        if (m.label == j.id && m.plane.known) {
          joint.source = "traces";
          for (const auto& t : m.traces) joint.source += " " + t;
          joint.type = "trace";
        }
    joints.push_back(joint);
  }
  store.save_joints(out.visit_id, {}, joints);
  // The rock-mass form the scene brings (what the geologist entered on site).
  if (scene->rockmass) store.save_rockmass_form(out.visit_id, *scene->rockmass);

  progress.step("blocks", 0.8);
  analysis::Report report = analysis::analyse(analysed, progress);
  // What the synthetic camera simulated, named as the analysis's effects are.
  for (const auto& e : synthetic->scene.effects.simulated())
    report.effects_simulated.push_back("imaging." + e);
  const storage::AnalysisRun run = analysis_record(report, out.visit_id, out.model_id, chosen);
  out.analysis_id = store.save_analysis(run);
  out.report = std::move(report);
  progress.step("done", 1.0);
  return out;
}

}  // namespace rockface::app
