#include "firmware-app/replay/field_replay.h"
#include "core/analysis/preset_options.h"
#include "firmware-app/replay/field_replay_phases.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "camera/capture_guidance.h"
#include "camera/exif.h"
#include "camera/mock_camera.h"
#include "camera/synthetic_renderer.h"
#include "core/analysis/scene_analysis.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
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
#include "firmware-app/replay/replay_refusal_undo.h"
#include "firmware-app/tunnel/replay_tunnel.h"
#include "storage/project/calibration_library.h"
#include "storage/project/project_store.h"
#include "storage/project/visit_geologist.h"
#include "storage/report/reconstruction_report.h"
#include "storage/scene/camera_json.h"
#include "storage/scene/scene.h"
#include "storage/scene/visit_file_json.h"
#include "storage/tunnel/visit_heading.h"

namespace rockface::app {

namespace field_replay_phases {

namespace fs = std::filesystem;

namespace {

bool given_any(const RegistrationOptions& o) {
  return o.range_pole || o.azimuth || !o.reference_line.empty() || o.declination ||
         !o.gcp.empty() || o.baseline;
}

}  // namespace

ReplaySource open_source(const ReplayRequest& request) {
  const bool from_scene = fs::is_regular_file(request.source);
  if (!from_scene && !fs::is_directory(request.source))
    throw InputError(request.source, "neither a scene file nor a folder of captures");
  ReplaySource out;
  out.spool = fs::path(request.project).parent_path() /
              (fs::path(request.project).filename().string() + ".spool");
  if (from_scene) {
    out.scene = storage::load_scene(request.source);
    out.synthetic = synthetic_scene_from_scene(*out.scene);
    // A pick naming a pair the scene does not photograph, or a pixel outside
    // the photographs: bad input before anything is captured or stored.
    check_picks_before_capture(*out.scene, std::max<std::size_t>(1, out.synthetic->pairs.size()));
    // A typed placement off the alignment: refused before the camera
    // spools a shot or the project is created (issue 41).
    try {
      out.typed_pole = typed_range_pole(*out.scene);
    } catch (const InputError& e) {
      throw InputError(request.source, e.what());  // the scene named, as its reader names it
    }
    out.camera = camera::MockCamera::synthetic(out.synthetic->scene, out.spool.string());
    out.intrinsics = camera::rendered_intrinsics(out.synthetic->scene);
    out.intrinsics.body = "rockface synthetic camera";
    if (out.synthetic->scene.range_pole)
      out.sources.range_pole_m = out.synthetic->scene.range_pole->length;
    out.sources.north = compass_reading(out.synthetic->scene, out.intrinsics, out.scene->source);
    // The survey's monitoring targets, tapped where the left photograph
    // shows them: ground control, which takes the place of the pole and
    // the compass line (reconstruction.h).
    out.sources.control_points = scene_control_points(*out.synthetic, out.intrinsics);
    out.sources.control_points_where = out.scene->source + ": imaging.control_targets";
  } else {
    const fs::path cam_file = fs::path(request.source) / "camera.json";
    if (fs::exists(cam_file)) {
      out.intrinsics = storage::load_camera_json(cam_file.string());
    } else if (fs::exists(request.project)) {
      out.calibration_from_library = true;
    } else {
      throw InputError(cam_file.string(),
                       "a capture folder needs the calibration of its camera: camera.json "
                       "beside the photographs, or a project whose calibrations hold it");
    }
    std::optional<Preset> preset = request.preset;
    out.sources =
        folder_registration(request.registration, fs::path(request.source) / "visit.json", preset,
                            out.visit_note, out.visit_heading, out.visit_geologist);
    out.camera = camera::MockCamera::replay(request.source, out.spool.string());
    out.preset = preset.value_or(Preset::standard);
    return out;
  }
  if (given_any(request.registration))
    throw InputError(request.source,
                     "a scene gives its own range pole and compass line (imaging.range_pole, "
                     "imaging.reference_line): --range-pole, --azimuth, --reference-line, "
                     "--declination, --gcp and --baseline are for a folder of photographs");
  out.preset = request.preset.value_or(out.scene->analysis.preset);
  return out;
}

photogrammetry::RegistrationSources folder_registration(const RegistrationOptions& given,
                                                        const fs::path& visit_file,
                                                        std::optional<Preset>& preset,
                                                        std::string& note, std::string& heading,
                                                        std::string& geologist) {
  RegistrationOptions o = given;
  if (fs::exists(visit_file)) {
    const storage::VisitFile v = storage::load_visit_file(visit_file.string());
    const std::string at = visit_file.string() + ": ";
    if (!o.range_pole && v.range_pole_m) {
      o.range_pole = v.range_pole_m;
      o.range_pole_name = at + "range_pole_m";
    }
    // The compass line is one reading: taken whole from the options when
    // they give any of it, else from the file.
    if (!o.azimuth && o.reference_line.empty() && !o.declination && v.azimuth_deg) {
      const auto& line = *v.reference_line_px;
      o.azimuth = v.azimuth_deg;
      o.declination = v.declination_deg;
      o.reference_line =
          format_significant(line[0].x(), 17) + "," + format_significant(line[0].y(), 17) + "," +
          format_significant(line[1].x(), 17) + "," + format_significant(line[1].y(), 17);
      o.azimuth_name = at + "compass.azimuth_deg";
      o.reference_line_name = at + "compass.reference_line_px";
      o.declination_name = at + "compass.declination_deg";
    }
    if (o.gcp.empty()) o.gcp = v.control_points;
    if (!o.baseline && v.baseline_m) {
      o.baseline = v.baseline_m;
      o.baseline_name = at + "baseline_m";
    }
    if (!preset) preset = v.preset;
    note = v.note;
    heading = v.heading;
    geologist = v.geologist;
  }
  return registration_sources(o);
}

CapturedPair capture_pair(camera::MockCamera& camera) {
  CapturedPair out;
  camera.lock_focus();
  out.left = camera.capture();
  out.right = camera.capture();
  camera::require_same_optics(out.left.exif, out.right.exif);
  for (const auto& note : camera::check_pair(out.left.exif, out.right.exif))
    out.guidance.push_back(note.text);
  return out;
}

StoredCapture store_capture(storage::ProjectStore& store, const ReplayRequest& request,
                            const ReplaySource& source, const CapturedPair& pair,
                            storage::RecordId visit_id, const std::string& preset_name) {
  const camera::Capture& left = pair.left;
  const camera::Capture& right = pair.right;
  storage::CameraBody body;
  body.make = left.exif.make.empty() ? "unknown" : left.exif.make;
  body.model = left.exif.model.empty() ? source.camera->model() : left.exif.model;
  body.serial = left.exif.serial.empty() ? left.body_serial : left.exif.serial;
  StoredCapture out;
  if (source.library_calibration_id) {
    out.calibration_id = *source.library_calibration_id;
  } else {
    storage::Calibration calibration;
    calibration.body_id = store.save_camera_body(body);
    calibration.intrinsics = source.intrinsics;
    calibration.focal_setting_mm = left.exif.focal_length_mm.value_or(0);
    calibration.method =
        source.scene ? "synthetic (rendering camera)" : "camera.json of " + request.source;
    out.calibration_id = store.save_calibration(calibration);
  }

  storage::Capture capture;
  capture.visit_id = visit_id;
  capture.calibration_id = out.calibration_id;
  capture.label = "replay pair";
  capture.left.bytes = left.image.data;
  capture.right.bytes = right.image.data;
  capture.left_exif = camera::exif_fields(left.exif);
  capture.right_exif = camera::exif_fields(right.exif);
  capture.settings["preset"] = preset_name;
  storage::record_camera(capture, camera::photo_camera(left.exif));
  out.capture_id = store.save_capture(capture);
  return out;
}

storage::Calibration library_calibration(storage::ProjectStore& store, const ReplayRequest& request,
                                         const CapturedPair& pair) {
  photogrammetry::PhotoCamera photo = camera::photo_camera(pair.left.exif);
  if (photo.width == 0 || photo.height == 0) {
    // No pixel size in the EXIF: the photograph's own.
    const cv::Mat image = decode_shot(pair.left.image, "left");
    photo.width = image.cols;
    photo.height = image.rows;
  }
  const storage::CalibrationChoice choice = storage::choose_calibration(store, photo);
  if (!choice.calibration) throw InputError(request.source, choice.refusal);
  return *choice.calibration;
}

photogrammetry::ReconstructionResult reconstruct_pair(
    const cv::Mat& left_image, const cv::Mat& right_image, const ReplaySource& source,
    const photogrammetry::ReconstructionPreset& preset, Progress& progress) {
  photogrammetry::ReconstructionResult rec =
      photogrammetry::reconstruct(left_image, right_image, source.intrinsics, source.intrinsics,
                                  preset, source.sources, progress);
  // In a tunnel the geologist may type where the pole stood (chainage,
  // offset, height) instead of surveying it.
  if (source.synthetic && source.synthetic->scene.range_pole && rec.targets && !rec.control_points)
    move_to_pole(rec, source.typed_pole.value_or(source.synthetic->scene.range_pole->base));
  return rec;
}

void rebase_to_datum(photogrammetry::ReconstructionResult& rec, const Eigen::Vector3d& datum) {
  // Only control points put the model about a datum of their own; else it
  // is already in the frame the replay gives it (the scene's, datum-relative).
  if (!rec.control_points) return;
  const Eigen::Vector3d shift = rec.datum - datum;
  if (shift.isZero(0)) return;
  rec.mesh.transform(1.0, Eigen::Matrix3d::Identity(), shift);
  rec.model_to_world.t += shift;
  if (rec.control_points) {
    rec.control_points->transform.t += shift;
    rec.control_points->datum = datum;
  }
  rec.datum = datum;
}

void move_to_pole(photogrammetry::ReconstructionResult& rec, const Eigen::Vector3d& pole) {
  const Eigen::Vector3d shift = pole - rec.model_to_world.apply(rec.targets->model[0]);
  rec.mesh.transform(1.0, Eigen::Matrix3d::Identity(), shift);
  rec.model_to_world.t += shift;
}

namespace {

// Where the left photograph shows scene points (distortion included): the
// pixels a geologist taps.
std::vector<cv::Point2d> left_pixels(const camera::SyntheticScene& scene,
                                     const photogrammetry::CameraIntrinsics& k,
                                     const std::vector<Eigen::Vector3d>& points) {
  const photogrammetry::CameraPose pose =
      camera::station_pose(scene.stations[0], "imaging.stations[0]");
  std::vector<cv::Point3d> world;
  for (const auto& p : points) world.emplace_back(p.x(), p.y(), p.z());
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
  return px;
}

}  // namespace

std::optional<photogrammetry::NorthReference> compass_reading(
    const camera::SyntheticScene& scene, const photogrammetry::CameraIntrinsics& k,
    const std::string& source) {
  if (!scene.reference_line) return std::nullopt;
  const auto& [from, to] = *scene.reference_line;
  const std::vector<cv::Point2d> px = left_pixels(scene, k, {from, to});
  photogrammetry::NorthReference north;
  north.from_px = {px[0].x, px[0].y};
  north.to_px = {px[1].x, px[1].y};
  north.azimuth_deg = rad_to_deg(std::atan2(to.x() - from.x(), to.y() - from.y()));
  if (north.azimuth_deg < 0) north.azimuth_deg += 360;
  // The scene's field, not the option of `reconstruct` (issue 41).
  north.where = source + ": imaging.reference_line";
  return north;
}

std::vector<photogrammetry::ControlPoint> scene_control_points(
    const SyntheticSceneInput& synthetic, const photogrammetry::CameraIntrinsics& k) {
  std::vector<photogrammetry::ControlPoint> out;
  const auto& targets = synthetic.scene.control_targets;
  if (targets.empty()) return out;
  std::vector<Eigen::Vector3d> centres;
  for (const auto& t : targets) centres.push_back(t.centre);
  const std::vector<cv::Point2d> px = left_pixels(synthetic.scene, k, centres);
  for (std::size_t i = 0; i < targets.size(); ++i)
    out.push_back({targets[i].id, {px[i].x, px[i].y}, targets[i].centre + synthetic.origin});
  return out;
}

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

std::vector<analysis::SceneTrace> true_face_traces(const storage::Scene& scene,
                                                   const SyntheticSceneInput& synthetic) {
  std::vector<analysis::SceneTrace> out;
  int n = 0;
  for (const auto& seg : camera::true_trace_segments(synthetic.scene)) {
    if (scene.tunnel && scene.tunnel->render && seg.patch.rfind("FACE", 0) != 0) continue;
    out.push_back({"T" + std::to_string(++n),
                   seg.joint,
                   {seg.world[0] + synthetic.origin, seg.world[1] + synthetic.origin}});
  }
  return out;
}

std::vector<analysis::ScenePatch> rendered_face(const SyntheticSceneInput& synthetic) {
  std::vector<analysis::ScenePatch> out;
  for (const auto& p : synthetic.scene.patches)
    if (p.id.rfind("FACE", 0) == 0) {
      out.push_back({p.id, {}});
      for (const auto& x : p.polygon) out.back().polygon.push_back(x + synthetic.origin);
    }
  return out;
}

analysis::AnalysisInput replay_analysis_input(const storage::Scene& scene,
                                              const SyntheticSceneInput& synthetic,
                                              const ReplayPicks* picked,
                                              const std::string& source_name) {
  analysis::AnalysisInput analysed = analysis_input(scene);
  if (picked) {
    analysed.traces = picked->traces;
    analysed.joints = picked->joints;
  }
  if (analysed.traces.empty()) analysed.traces = true_face_traces(scene, synthetic);
  if (analysed.patches.empty() && scene.tunnel && scene.tunnel->render)
    analysed.patches = rendered_face(synthetic);
  if (analysed.patches.empty())
    throw InputError(source_name, "surface.patches: the scene has no free surface");
  return analysed;
}

std::vector<storage::Measurement> visit_measurements(const analysis::AnalysisInput& analysed,
                                                     const ReplayPicks* picked,
                                                     const MorePairsOutcome* more,
                                                     const VisitRecordIds& ids,
                                                     const Eigen::Vector3d& datum) {
  std::vector<storage::Measurement> measurements;
  auto measured = [&](storage::Measurement::Kind kind, const std::string& label,
                      const std::vector<Eigen::Vector3d>& absolute) {
    storage::Measurement m;
    m.visit_id = ids.visit_id;
    m.model_id = ids.model_id;
    m.kind = kind;
    m.label = label;
    for (const auto& p : absolute) m.points.push_back(p - datum);
    return m;
  };
  if (picked) {
    // Each measurement with its own pair's model and capture.
    std::map<std::string, PairRecords> further;
    if (more)
      for (std::size_t k = 0; k < more->model_ids.size(); ++k)
        further[measure::pair_photo(static_cast<int>(k) + 2, "left")] = {more->model_ids[k],
                                                                         more->capture_ids[k]};
    measurements = measurement_records(picked->measured, ids.visit_id,
                                       {ids.model_id, ids.capture_id}, further);
    join_trace_records(picked->joined, measurements);
  } else
    for (const auto& t : analysed.traces) {
      measurements.push_back(measured(storage::Measurement::Kind::trace, t.id, t.points));
      measurements.back().joint_label = t.joint.value_or("");
    }
  for (const auto& patch : analysed.patches)
    measurements.push_back(measured(storage::Measurement::Kind::area, patch.id, patch.polygon));
  return measurements;
}

std::vector<storage::Joint> visit_joints(const analysis::AnalysisInput& analysed,
                                         const ReplayPicks* picked, storage::RecordId visit_id,
                                         const Eigen::Vector3d& datum) {
  std::vector<storage::Joint> joints;
  for (const auto& j : analysed.joints) {
    storage::Joint joint;
    joint.visit_id = visit_id;
    joint.label = j.id;
    joint.dip_deg = j.dip;
    joint.dipdir_deg = j.dipdir;
    if (j.point) joint.point = *j.point - datum;
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
  return joints;
}

}  // namespace field_replay_phases

namespace {

// The replay once its source is read: the pair captured, the project opened
// or created, and everything it stores saved in one transaction (a refusal
// part-way stores nothing).
ReplayOutcome replay_into_project(const ReplayRequest& request,
                                  field_replay_phases::ReplaySource& source, Progress& progress) {
  using namespace field_replay_phases;
  ReplayOutcome out;
  photogrammetry::ReconstructionPreset preset =
      analysis::preset_options(source.preset).reconstruction;

  progress.step("capture", 0.0);
  const CapturedPair pair = capture_pair(*source.camera);
  out.guidance = pair.guidance;

  storage::ProjectInfo info;
  info.name = source.scene && !source.scene->name.empty()
                  ? source.scene->name
                  : fs::path(request.source).filename().string();
  if (source.scene) info.datum = source.scene->datum;
  // A folder on control points: a new project's datum near the work (their
  // centroid to the metre), so its coordinates stay small (issue 40's rule).
  if (!source.scene && !source.sources.control_points.empty()) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& p : source.sources.control_points) c += p.world;
    info.datum = (c / static_cast<double>(source.sources.control_points.size())).array().round();
  }
  storage::ProjectStore store = storage::ProjectStore::open_or_create(request.project, info);
  if (store.read_only())
    throw InputError(request.project, "cannot replay into it: " + store.read_only_reason());
  // A tunnel round's 3D image is measured against the tunnel's design: its
  // lining, seen along the drive, is matched for it (preset.h).
  preset.lining_along_the_drive =
      (source.scene && source.scene->tunnel) || store.load_tunnel().has_value();
  // A folder without camera.json: its camera's calibration from the
  // project's library, chosen before the visit begins (a refusal stores
  // nothing).
  if (source.calibration_from_library) {
    const storage::Calibration c = library_calibration(store, request, pair);
    source.intrinsics = c.intrinsics;
    source.library_calibration_id = c.id;
  }
  // One transaction from the visit's start to its analysis: a refusal after
  // the visit began (a face off the alignment, picks the analysis refuses)
  // leaves an existing project as it was, byte for byte (issue 41).
  store.in_one_transaction("replaying " + request.source, [&] {
    out.visit_id =
        store.begin_visit("replay " + request.source, source.visit_note, source.visit_geologist);
    const StoredCapture stored =
        store_capture(store, request, source, pair, out.visit_id, preset.name);
    out.capture_id = stored.capture_id;

    const cv::Mat left_image = decode_shot(pair.left.image, "left");
    const cv::Mat right_image = decode_shot(pair.right.image, "right");
    photogrammetry::ReconstructionResult rec =
        reconstruct_pair(left_image, right_image, source, preset, progress);
    rebase_to_datum(rec, store.project().datum);
    const storage::Model model = model_record(
        rec, out.capture_id,
        {pair.left.image.saved_path, pair.right.image.saved_path, preset.name,
         source.sources.range_pole_m, source.sources.baseline_m, source.sources.north});
    out.model_id = store.save_model(model);
    std::optional<MorePairsOutcome> more;
    if (source.synthetic && source.synthetic->pairs.size() > 1) {
      more = replay_more_pairs(store,
                               {out.visit_id, stored.calibration_id, &*source.synthetic,
                                source.intrinsics, preset.name, preset, source.spool},
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
    if (rec.control_points)
      out.registration += " (" + photogrammetry::control_points_summary(*rec.control_points) + ")";
    out.predicted_depth_sigma_m = rec.accuracy.sigma_z;
    out.scaled = rec.scaled;
    for (const auto& w : rec.accuracy.warnings) out.guidance.push_back(w);

    if (!source.scene) return;  // a capture folder has no traces to analyse
    const storage::Scene& scene = *source.scene;
    if (scene.tunnel) out.guidance.push_back(place_replayed_visit(store, scene, out.visit_id));

    // Traces: measured on the reconstructed image where the scene gives picks
    // (replay_picks.h); else those of the scene, or the synthetic scene's true
    // traces (what the geologist would mark on the model).
    std::optional<ReplayPicks> picked;
    if (scene.picks) {
      progress.step("measure", 0.75);
      picked = measure_replay_picks(scene, rec, source.intrinsics, preset, left_image, right_image,
                                    more ? &*more : nullptr);
      for (const auto& note : picked->notes) out.guidance.push_back(note);
      out.joints = joint_comparisons(scene, picked->measured);
    }
    const ReplayPicks* picks = picked ? &*picked : nullptr;
    const analysis::AnalysisInput analysed =
        replay_analysis_input(scene, *source.synthetic, picks, request.source);
    // The traces, and the free surface as areas: with the joints below, the
    // visit holds all the analysis needs, so it can be analysed again from
    // the project alone (the tablet UI does).
    store.save_measurements(
        out.visit_id,
        visit_measurements(analysed, picks, more ? &*more : nullptr,
                           {out.visit_id, out.model_id, out.capture_id}, scene.datum));
    store.save_joints(out.visit_id, {}, visit_joints(analysed, picks, out.visit_id, scene.datum));
    // The rock-mass form the scene brings (what the geologist entered on site).
    if (scene.rockmass) store.save_rockmass_form(out.visit_id, *scene.rockmass);

    progress.step("blocks", 0.8);
    analysis::Report report = analysis::analyse(analysed, progress);
    // What the synthetic camera simulated, named as the analysis's effects are.
    for (const auto& e : source.synthetic->scene.effects.simulated())
      report.effects_simulated.push_back("imaging." + e);
    const storage::AnalysisRun run =
        analysis_record(report, out.visit_id, out.model_id, source.preset);
    out.analysis_id = store.save_analysis(run);
    out.report = std::move(report);
  });
  progress.step("done", 1.0);
  return out;
}

}  // namespace

ReplayOutcome replay_field_workflow(const ReplayRequest& request, Progress& progress) {
  // A refusal while the source is read leaves nothing: nothing is written yet.
  const std::string given_heading = storage::checked_heading(request.heading, "--heading");
  const std::string given_geologist = storage::checked_geologist(request.geologist, "--geologist");
  field_replay_phases::ReplaySource source = field_replay_phases::open_source(request);
  // The option wins over the visit file; the visit begins with it.
  if (!given_geologist.empty()) source.visit_geologist = given_geologist;
  const ReplayRefusalUndo undo(request.project, source.spool);
  try {
    ReplayOutcome out = replay_into_project(request, source, progress);
    out.geologist = source.visit_geologist;
    // After the replay's one transaction, on the visit it made: the name
    // was checked before anything was stored.
    out.heading = given_heading.empty() ? source.visit_heading : given_heading;
    if (!out.heading.empty()) {
      storage::ProjectStore store = storage::ProjectStore::open(request.project);
      storage::save_visit_heading(store, out.visit_id, out.heading);
    }
    return out;
  } catch (const InputError& e) {
    undo.remove_what_the_replay_made();
    throw InputError(e.where(), undo.said(e.reason()));
  } catch (...) {
    // The store is closed (unwound) by now: its file can go.
    undo.remove_what_the_replay_made();
    throw;
  }
}

}  // namespace rockface::app
