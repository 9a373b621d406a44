#include "storage/field_report/field_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/Geometry>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/measure/joint_sets.h"
#include "storage/project/calibration_library.h"
#include "storage/project/model_registration.h"
#include "storage/scene/export_scene_json.h"
#include "storage/scene/face_outline_words.h"

namespace rockface::storage {

namespace {

// The reconstruction report stored with the first model (rockface-reconstruction/1).
void read_accuracy(const ModelRegistration& reg, ReportedAccuracy& a) {
  if (reg.record != ModelRegistration::Record::reconstruction) return;
  a.sigma_z_m = reg.sigma_z_m;
  a.distance_m = reg.distance_m;
  a.point_spacing_m = reg.point_spacing_m;
  a.reprojection_rms_px = reg.rms_reprojection_px;
  if (reg.inliers) a.tie_points = static_cast<int>(*reg.inliers);
  a.imported_from = reg.imported_from;
  a.scale_source = reg.scale_source;
  a.vertical_source = reg.vertical_source;
  a.north_source = reg.north_source;
  a.scale = reg.scale;
  a.range_pole_m = reg.pole_length_m;
  a.compass_azimuth_deg = reg.compass_azimuth_deg;
  a.declination_deg = reg.declination_deg;
  a.north_rotation_deg = reg.north_rotation_deg;
  if (reg.has_control_points) {
    a.control_rms_m = reg.control_rms_m;
    for (const auto& p : reg.control_points) a.control_points.push_back({p.id, p.distance_m});
  }
  a.warnings.insert(a.warnings.end(), reg.warnings.begin(), reg.warnings.end());
}

// The face registration stored with a further model (rockface-face-registration/1).
void read_face_registration(const ModelRegistration& reg, ReportedAccuracy& a) {
  if (reg.record != ModelRegistration::Record::face_images) return;
  for (const auto& i : reg.images)
    a.images.push_back({i.name, i.role, i.reference, static_cast<int>(i.tie_points.value_or(0.0)),
                        i.overlap.value_or(0.0), i.surface_rms_m.value_or(0.0), i.scale});
  if (reg.has_control_points) {
    a.control_rms_m = reg.control_rms_m;
    a.control_points.clear();
    for (const auto& p : reg.control_points) a.control_points.push_back({p.id, p.distance_m});
  }
}

// Returns, when the poles are the planes measured on the face, each
// trace's pole (by the label of its first piece): r.pole_sets then gives
// its cluster.
std::map<std::string, std::size_t> joints_and_sets(ProjectStore& store, FieldReport& r) {
  for (const auto& j : store.list_joints(r.visit_id)) {
    r.joints.push_back(
        {j.label, j.set_label, j.source, j.dip_deg, j.dipdir_deg, j.friction_deg, j.cohesion_pa});
    r.poles.push_back(geometry::plane_normal_deg(j.dip_deg, j.dipdir_deg));
  }
  r.pole_sets.assign(r.poles.size(), -1);
  const auto stored = store.list_joint_sets(r.visit_id);
  if (!stored.empty()) {
    for (const auto& s : stored) {
      ReportedJointSet set{s.label, s.count, s.dip_deg, s.dipdir_deg, s.fisher_k, {}, "stored"};
      r.sets.push_back(set);
    }
    for (std::size_t i = 0; i < r.joints.size(); ++i)
      for (std::size_t k = 0; k < r.sets.size(); ++k)
        if (r.joints[i].set_label == r.sets[k].label) r.pole_sets[i] = static_cast<int>(k);
    return {};
  }
  // No sets stored: they are clustered here (core/measure), as the tablet
  // would offer: from the planes measured on the face when there are two or
  // more, else from the joints. A trace joined from pieces stored on
  // different pairs (scene_traces) is one discontinuity: one pole, the mean
  // of its pieces' planes.
  const std::vector<Measurement> measurements = store.list_measurements(r.visit_id);
  std::map<std::string, std::vector<Eigen::Vector3d>> joined_poles;  // by the joined trace's label
  std::map<std::string, std::string> joined_into;                    // piece label -> trace label
  for (const auto& t : scene_traces(measurements))
    if (t.pieces.size() > 1)
      for (const auto& piece : t.pieces) joined_into[piece] = t.label;
  std::vector<Eigen::Vector3d> measured;
  std::map<std::string, std::size_t> pole_of_trace;
  for (const auto& m : measurements) {
    if (!m.dip_deg || !m.dipdir_deg) continue;
    const Eigen::Vector3d pole = geometry::plane_normal_deg(*m.dip_deg, *m.dipdir_deg);
    const auto joined =
        m.kind == Measurement::Kind::trace ? joined_into.find(m.label) : joined_into.end();
    if (joined == joined_into.end()) {
      if (m.kind == Measurement::Kind::trace) pole_of_trace[m.label] = measured.size();
      measured.push_back(pole);
    } else {
      joined_poles[joined->second].push_back(pole);
    }
  }
  for (const auto& [label, poles] : joined_poles) {
    pole_of_trace[label] = measured.size();
    measured.push_back(measure::fisher_statistics(poles).mean);
  }
  const bool from_measured = measured.size() >= 2;
  if (from_measured) r.poles = measured;
  if (r.poles.size() < 2) return {};
  const measure::PoleClusters clusters = measure::cluster_poles(r.poles, {});
  const std::string origin =
      from_measured ? "clustered from " + std::to_string(measured.size()) + " measured planes"
                    : "clustered from the joints";
  for (std::size_t k = 0; k < clusters.sets.size(); ++k) {
    const auto& f = clusters.sets[k];
    const geometry::PlaneOrientation o = f.plane();
    ReportedJointSet set{"S" + std::to_string(k + 1),
                         static_cast<int>(f.count),
                         rad_to_deg(o.dip),
                         rad_to_deg(o.dipdir),
                         f.kappa,
                         {},
                         origin};
    if (f.count >= 2 && f.alpha95 < M_PI) set.alpha95_deg = rad_to_deg(f.alpha95);
    r.sets.push_back(set);
  }
  r.pole_sets = clusters.set_of;
  if (!from_measured)
    for (std::size_t i = 0; i < r.joints.size(); ++i)
      if (r.pole_sets[i] >= 0) r.joints[i].set_label = r.sets[r.pole_sets[i]].label;
  return from_measured ? pole_of_trace : std::map<std::string, std::size_t>{};
}

// Each trace's set (FieldReport::trace_sets): its joint's set, else its own
// plane's cluster.
std::vector<int> sets_of_traces(const FieldReport& r,
                                const std::vector<photogrammetry::FaceTrace>& traces,
                                const std::map<std::string, std::size_t>& pole_of_trace) {
  std::vector<int> out;
  for (const auto& t : traces) {
    int set = -1;
    for (const auto& j : r.joints)
      if (!t.joint.empty() && j.label == t.joint)
        for (std::size_t k = 0; k < r.sets.size(); ++k)
          if (!j.set_label.empty() && r.sets[k].label == j.set_label) set = static_cast<int>(k);
    const auto pole = pole_of_trace.find(t.label);
    if (set < 0 && pole != pole_of_trace.end() && pole->second < r.pole_sets.size())
      set = r.pole_sets[pole->second];
    out.push_back(set);
  }
  return out;
}

// The face's planes: each outline's first flat piece, and each free face
// (an area with the rock's side), with the area of its outline.
std::vector<ReportedFacePlane> face_planes(const std::vector<Measurement>& measurements,
                                           const std::vector<Joint>& joints) {
  std::vector<ReportedFacePlane> out;
  for (const auto& m : measurements) {
    if (m.kind != Measurement::Kind::area) continue;
    const bool free_face = !m.rock_side.empty();
    if (!free_face && !is_face_outline(m, joints)) continue;
    const std::string label = free_face ? m.label : outline_of_piece(m.label);
    if (std::any_of(out.begin(), out.end(), [&](const auto& f) { return f.label == label; }))
      continue;
    // Newell's sum: twice the outline's vector area, normal to its plane.
    Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < m.points.size(); ++i)
      twice_area += m.points[i].cross(m.points[(i + 1) % m.points.size()]);
    ReportedFacePlane f{label, 0, 0, 0.5 * twice_area.norm(), true};
    if (m.dip_deg && m.dipdir_deg) {
      f.dip_deg = *m.dip_deg;
      f.dipdir_deg = *m.dipdir_deg;
    } else if (f.area_m2 > 0) {
      // An outline stored without its plane (a scene's free face): the
      // plane its corners span.
      const geometry::PlaneOrientation o = geometry::plane_orientation(twice_area);
      f.dip_deg = rad_to_deg(o.dip);
      f.dipdir_deg = rad_to_deg(o.dipdir);
      f.oriented = false;
    } else {
      continue;
    }
    out.push_back(f);
  }
  return out;
}

}  // namespace

FieldReport collect_field_report(ProjectStore& store, RecordId visit_id) {
  FieldReport r;
  const ProjectInfo info = store.project();
  r.project_name = info.name;
  r.project_file = store.file().string();
  r.datum = info.datum;
  r.visit_id = visit_id;
  bool found = false;
  for (const auto& v : store.list_visits())
    if (v.id == visit_id) {
      found = true;
      r.visit_started_at = v.started_at;
      r.visit_source = v.source;
      r.visit_geologist = v.geologist;
    }
  if (!found)
    throw InputError("--visit",
                     "the project " + r.project_file + " has no visit " + std::to_string(visit_id));

  const auto captures = store.list_captures(visit_id);
  bool first_model = true;
  for (const auto& c : captures) {
    // Each pair's newest 3D image (as list_visit_models): north given after
    // the reconstruction (the tablet's compass line, `rockface orient`)
    // stores the visit's models turned anew, the first one unturned (issue
    // 42: a visit oriented on the tablet was reported "north: none").
    const std::vector<ModelSummary> models = store.list_models(c.id);
    if (models.empty()) continue;
    const Model m = store.load_model(models.back().id);
    if (first_model) {
      first_model = false;
      r.preset = m.preset;
      const photogrammetry::Similarity s = similarity_of(m.registration);
      r.model_scale = s.scale;
      r.model_rotation = s.R;
      r.model_translation = s.t;
      read_accuracy(read_model_registration(m.registration), r.accuracy);
      const ImageBlob left = store.load_capture_image(c.id, "left");
      // A copy pulled without its photographs (the office's visit pages,
      // which fetch each photograph they show) reports none.
      if (!left.bytes.empty()) r.photograph = cv::imdecode(left.bytes, cv::IMREAD_COLOR);
      if (c.calibration_id) {
        const Calibration cal = store.load_calibration(*c.calibration_id);
        r.intrinsics = cal.intrinsics;
        r.calibration_known = true;
        r.calibration_method = cal.method;
        r.lens = cal.intrinsics.lens;
        for (const auto& b : store.list_camera_bodies())
          if (cal.body_id && b.id == *cal.body_id) r.camera_body = b.make + " " + b.model;
      }
      // The body that took the pair, as the capture recorded it (its
      // serial from USB where the photograph's EXIF has none).
      if (auto taken = recorded_camera(store.load_capture(c.id))) {
        taken->lens.clear();
        taken->focal_mm.reset();
        taken->width = taken->height = 0;
        r.camera_body = taken->described();
      }
    } else {
      read_face_registration(read_model_registration(m.registration), r.accuracy);
    }
  }
  // The traces as the analysis takes them: the pieces of one trace stored
  // from different pairs' models joined into one (scene_traces), drawn as
  // one line and labelled by its pieces ("T1+T4").
  const std::vector<Measurement> stored = store.list_measurements(visit_id);
  for (const auto& m : stored)
    if (m.kind == Measurement::Kind::trace)
      ++(m.origin == "proposed"    ? r.traces_proposed
         : m.origin == "corrected" ? r.traces_corrected
                                   : r.traces_by_hand);
  const std::vector<photogrammetry::FaceTrace> traces = scene_traces(stored);
  for (const auto& t : traces) {
    std::string label = t.label;
    for (std::size_t k = 1; k < t.pieces.size(); ++k) label += "+" + t.pieces[k];
    r.traces.emplace_back(label, t.points);
  }
  const auto pole_of_trace = joints_and_sets(store, r);
  r.trace_sets = sets_of_traces(r, traces, pole_of_trace);
  // Issue 27: the mapped face as the geologist outlined it, in its flat
  // pieces (storage/scene/face_outline_words.h); the outlines of one flat
  // piece in one line (issue 39: a face of many filled page 1).
  const auto joints = store.list_joints(visit_id);
  r.face_outlines = face_outline_summary(stored, joints);
  r.face_planes = face_planes(stored, joints);

  const auto runs = store.list_analyses(visit_id);
  if (!runs.empty()) {
    const AnalysisRun run = store.load_analysis(runs.back().id);
    r.analysis_id = run.id;
    r.effects = run.effects;
    if (r.preset.empty()) r.preset = run.preset;
    r.blocks = run.blocks;
  }
  return r;
}

std::string report_number(double value, int decimals) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (!std::isfinite(value)) return "-";
  std::string s = format_fixed(value, decimals);
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // no "-0.00"
  return s;
}

std::string report_number(const std::optional<double>& value, int decimals) {
  return value ? report_number(*value, decimals) : "-";
}

std::string report_verdict(const analysis::ReportBlock& b) {
  return std::string(!b.finite ? "infinite" : (b.removable ? "removable" : "finite, keyed")) +
         (b.marginal ? "?" : "");
}

std::string report_mode(const analysis::ReportBlock& b) {
  const std::string mode = b.mode ? b.mode->type : "none";
  if (mode != "sliding" || b.mode->planes.empty()) return mode;
  const auto& planes = b.mode->planes;
  std::string s = "sliding on ";
  for (std::size_t i = 0; i < planes.size(); ++i) s += (i ? "+" : "") + planes[i];
  return s;
}

std::string report_rotation(const analysis::ReportBlock& b) {
  if (!b.rotation) return "-";
  const auto& r = *b.rotation;
  int rotatable_corners = 0, rotatable_edges = 0;
  for (const auto& c : r.corners) rotatable_corners += c.rotatable;
  for (const auto& e : r.edges) rotatable_edges += e.rotatable;
  std::string s = std::to_string(rotatable_corners) + "/" + std::to_string(r.corners.size()) +
                  " corners, " + std::to_string(rotatable_edges) + "/" +
                  std::to_string(r.edges.size()) + " edges";
  if (b.remote_axis) s += b.remote_axis->found ? "; remote axis" : "; no remote axis";
  return s;
}

}  // namespace rockface::storage
