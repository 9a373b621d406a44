// `rockface measure MODEL.ply|PROJECT --traces PICKS.json --out MEASURES.json
//  [--png STEREONET.png] [--csv DIPS.csv] [--sets N|auto]`
//
// Measures the picks on a 3D image: a model file (with the camera it was
// reconstructed with) or a project's model. Everything is measured before
// anything is written: a bad pick stops the verb (exit 2) naming it, with
// nothing stored and no output file.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/stereonet_image.h"
#include "core/photogrammetry/preset.h"
#include "firmware-app/atomic_file.h"
#include "firmware-app/measure_picks.h"
#include "firmware-app/project_mesh.h"
#include "firmware-app/verb_registry.h"
#include "storage/camera_json.h"
#include "storage/export_joints_csv.h"
#include "storage/ply_reader.h"
#include "storage/project_store.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;

struct MeasureOptions {
  std::string source, picks, out, png, csv, sets, camera, photo;
  std::optional<storage::RecordId> model;
  std::optional<double> point_sigma;
  double friction = 30;
};

// The 3D image and what it was seen from.
struct LoadedModel {
  photogrammetry::SurfaceMesh mesh;
  std::map<std::string, measure::PhotoView> views;
  std::map<std::string, cv::Mat> photos;
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  double point_sigma = 0.01;
  double correlation_length = 0;
  std::string name;
  // Project only.
  std::optional<storage::RecordId> model_id, capture_id;
};

cv::Mat decode(const std::vector<unsigned char>& bytes) {
  if (bytes.empty()) return {};
  try {
    return cv::imdecode(bytes, cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    return {};
  }
}

LoadedModel load_ply_model(const MeasureOptions& o) {
  if (o.camera.empty())
    throw InputError("--camera",
                     "a model file needs the calibration of the camera it was "
                     "reconstructed with (the --camera of `rockface reconstruct`)");
  const photogrammetry::CameraIntrinsics camera = storage::load_camera_json(o.camera);
  storage::PlyModel ply = storage::read_ply_mesh(o.source);
  LoadedModel m;
  m.datum = ply.datum;
  m.name = o.source;
  m.mesh = surface_mesh(std::move(ply.mesh), camera.width, camera.height);
  if (m.mesh.triangles.empty()) throw InputError(o.source, "the model has no triangles");
  if (m.mesh.pixels.empty())
    throw InputError(o.source,
                     "the model has no texture coordinates: its vertices cannot be "
                     "placed in the left photograph");
  m.views.emplace("left", measure::left_view_from_lattice(m.mesh, camera));
  const std::string photo = !o.photo.empty() ? o.photo : ply.texture_file;
  if (!photo.empty()) {
    m.photos["left"] = cv::imread(photo, cv::IMREAD_COLOR);
    if (!o.photo.empty() && m.photos["left"].empty())
      throw InputError("--photo", photo + " is not an image OpenCV can read");
  }
  // Without a report: the point precision given, else a tenth of a percent
  // of the distance to the face (sigma_Z of a 1/5 base at 0.2 px).
  const double distance = (m.views["left"].pose.centre - m.mesh.vertices[m.mesh.size() / 2]).norm();
  m.point_sigma = o.point_sigma.value_or(1e-3 * distance);
  m.correlation_length =
      m.mesh.median_edge_length() * photogrammetry::preset_standard().sgbm_block_size;
  return m;
}

LoadedModel load_project_model(storage::ProjectStore& store, const MeasureOptions& o) {
  storage::RecordId id = 0;
  if (o.model) {
    id = *o.model;
  } else {
    const auto models = store.list_models();
    if (models.empty()) throw InputError(o.source, "the project has no model to measure on");
    for (const auto& s : models) id = std::max(id, s.id);
  }
  storage::Model model;
  try {
    model = store.load_model(id);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError("--model", "no model " + std::to_string(id) + " in " + o.source);
  }
  LoadedModel m;
  m.model_id = id;
  m.name = o.source + " model " + std::to_string(id);
  m.datum = store.project().datum;
  if (!model.texture_capture_id || model.texture_side != "left")
    throw InputError(o.source, "model " + std::to_string(id) +
                                   " has no left photograph as texture: picks in a photograph "
                                   "cannot be placed on it");
  m.capture_id = model.texture_capture_id;
  const storage::Capture capture = store.load_capture(*model.texture_capture_id);
  if (!capture.calibration_id)
    throw InputError(o.source,
                     "the capture of model " + std::to_string(id) + " has no calibration");
  const auto intrinsics = store.load_calibration(*capture.calibration_id).intrinsics;
  const storage::Registration& r = model.registration;
  photogrammetry::Similarity model_to_world;
  model_to_world.scale = r.scale;
  model_to_world.R = Eigen::Quaterniond(r.rotation_wxyz[0], r.rotation_wxyz[1], r.rotation_wxyz[2],
                                        r.rotation_wxyz[3])
                         .normalized()
                         .toRotationMatrix();
  model_to_world.t = r.translation;
  m.views.emplace("left", measure::left_view(model_to_world, intrinsics));
  m.photos["left"] = decode(capture.left.bytes);
  // The report of the reconstruction: the right camera's relative
  // orientation and the predicted precision of a point.
  const auto p =
      nlohmann::json::parse(r.parameters_json.empty() ? "{}" : r.parameters_json, nullptr, false);
  if (p.is_object() && p.contains("orientation") && p["orientation"].contains("R") &&
      p["orientation"].contains("t")) {
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) R(i, k) = p["orientation"]["R"][i][k].get<double>();
      t[i] = p["orientation"]["t"][i].get<double>();
    }
    m.views.emplace("right", measure::right_view(model_to_world, R, t, intrinsics));
    m.photos["right"] = decode(capture.right.bytes);
  }
  m.mesh = surface_mesh(std::move(model.mesh), intrinsics.width, intrinsics.height);
  if (m.mesh.triangles.empty())
    throw InputError(o.source, "model " + std::to_string(id) + " has no triangles");
  m.point_sigma = o.point_sigma.value_or(p.is_object() && p.contains("predicted_depth_sigma_mm")
                                             ? p["predicted_depth_sigma_mm"].get<double>() / 1000
                                             : 0.01);
  const auto preset = photogrammetry::preset_by_name(
      model.preset.empty() ? "standard" : model.preset, "model preset");
  m.correlation_length = m.mesh.median_edge_length() * preset.sgbm_block_size;
  return m;
}

cv::Mat stereonet(const MeasuredPicks& r, const std::string& title, double friction_deg) {
  measure::StereonetPicture pic;
  pic.title = title;
  for (std::size_t k = 0; k < r.poles.size(); ++k) {
    const PoleSource& s = r.poles[k];
    const auto& plane = s.kind == 't'   ? r.traces[s.index].m.plane
                        : s.kind == 'a' ? r.areas[s.index].m.plane
                                        : r.points[s.index].plane;
    pic.poles.push_back(plane.fit.normal);
    pic.pole_sets.push_back(r.clusters.set_of.empty() ? -1 : r.clusters.set_of[k]);
  }
  for (const auto& s : r.sets)
    pic.sets.push_back({s.label, s.fisher.plane(), s.fisher.alpha95 < M_PI ? s.fisher.alpha95 : 0});
  for (const auto& a : r.areas)
    if (!a.rock_side.empty() && a.m.plane.known) {
      pic.faces.push_back({a.m.id, a.m.plane.orientation});
      if (!pic.kinematics)
        pic.kinematics = measure::KinematicOverlay{a.m.plane.orientation, deg_to_rad(friction_deg)};
    }
  return measure::render_stereonet(pic);
}

int run(const MeasureOptions& o) {
  std::optional<int> sets;
  if (!o.sets.empty() && o.sets != "auto") {
    try {
      std::size_t used = 0;
      sets = std::stoi(o.sets, &used);
      if (used != o.sets.size()) throw std::invalid_argument(o.sets);
    } catch (const std::exception&) {
      throw InputError("--sets", "\"" + o.sets + "\" is not a count or \"auto\"");
    }
    if (*sets < 1 || *sets > 12) throw InputError("--sets", o.sets + " is outside [1, 12]");
  }
  if (!fs::exists(o.source)) throw InputError(o.source, "no such file");
  const storage::Picks picks = storage::load_picks(o.picks);
  // One model, one pair: picks in a further pair's photograph belong to a
  // replayed visit of several pairs (docs/scene-extensions.md).
  for (const auto& t : picks.traces)
    if (t.pair != 1)
      throw InputError(o.picks + ": " + t.where + ".pair",
                       "pair " + std::to_string(t.pair) +
                           ", but `rockface measure` measures one 3D image (pair 1)");
  if (!sets) sets = o.sets == "auto" ? std::nullopt : picks.sets;

  const bool ply = fs::path(o.source).extension() == ".ply";
  std::optional<storage::ProjectStore> store;
  LoadedModel model;
  if (ply) {
    model = load_ply_model(o);
  } else {
    store.emplace(storage::ProjectStore::open(o.source));
    if (store->read_only())
      throw InputError(o.source, "cannot store measurements in it: " + store->read_only_reason());
    model = load_project_model(*store, o);
  }
  const measure::MeshPicker picker(model.mesh);
  MeasureContext context;
  context.picker = &picker;
  context.views = model.views;
  context.photos = model.photos;
  context.settings.point_sigma = model.point_sigma;
  context.settings.correlation_length = model.correlation_length;
  context.datum = model.datum;
  context.source = o.picks;
  const MeasuredPicks measured = measure_picks(picks, context, sets);

  // Everything measured: now the store (one visit, each save one
  // transaction) and the outputs.
  std::vector<storage::Joint> joints = joint_records(measured, 0);
  if (store) {
    const storage::RecordId visit = store->begin_visit(
        "measure " + o.picks, "picks measured on model " + std::to_string(*model.model_id));
    const auto ids = store->save_measurements(
        visit, measurement_records(measured, visit, model.model_id, model.capture_id));
    const auto records = measurement_records(measured, visit, model.model_id, model.capture_id);
    for (auto& j : joints) {
      j.visit_id = visit;
      for (std::size_t k = 0; k < records.size(); ++k)
        if (records[k].label == j.label) j.measurement_id = ids[k];
    }
    store->save_joints(visit, joint_set_records(measured), joints);
    std::cout << "stored in " << o.source << ", visit " << visit << "\n";
  }
  const cv::Mat png = o.png.empty()
                          ? cv::Mat()
                          : stereonet(measured, fs::path(o.picks).filename().string(), o.friction);
  write_atomically(o.out, measures_json(measured, context, model.name));
  if (!png.empty() && !cv::imwrite(o.png, png)) throw Error(o.png + ": cannot write the picture");
  if (!o.csv.empty()) {
    std::ostringstream csv;
    storage::write_joints_csv(csv, joints, model.datum);
    write_atomically(o.csv, csv.str());
  }
  std::size_t known = 0;
  for (const auto& t : measured.traces) known += t.m.plane.known ? 1 : 0;
  std::cout << measured.traces.size() << " traces (" << known << " with a known plane), "
            << measured.areas.size() << " areas, " << measured.points.size() << " points; "
            << measured.sets.size() << " joint sets\n";
  for (const auto& s : measured.sets) {
    const auto pl = s.fisher.plane();
    std::printf("set %s: %zu planes, mean %.1f/%.1f, K %.1f, alpha95 %.1f deg\n", s.label.c_str(),
                s.fisher.count, rad_to_deg(pl.dip), rad_to_deg(pl.dipdir), s.fisher.kappa,
                rad_to_deg(s.fisher.alpha95));
  }
  return 0;
}

VerbRun setup_measure(CLI::App& sub) {
  auto o = std::make_shared<MeasureOptions>();
  sub.add_option("MODEL", o->source,
                 "a model file (MODEL.ply of `rockface reconstruct`) or a project (*.rockface)")
      ->required();
  sub.add_option("--traces", o->picks, "the picks (rockface-picks/1, docs/scene-extensions.md)")
      ->required();
  sub.add_option("--out", o->out, "the measurements (rockface-measures/1)")->required();
  sub.add_option("--png", o->png, "stereonet picture (lower hemisphere, equal area)");
  sub.add_option("--csv", o->csv, "Dips-style CSV of the measured planes");
  sub.add_option("--sets", o->sets,
                 "number of joint sets, or auto (default: the picks', else auto)");
  sub.add_option("--model", o->model, "project: the model id (default: the latest)");
  sub.add_option("--camera", o->camera, "model file: the camera it was reconstructed with");
  sub.add_option("--photo", o->photo,
                 "model file: the left photograph (default: the model's TextureFile)");
  sub.add_option("--point-sigma", o->point_sigma,
                 "precision of a picked point, m (default: the reconstruction's sigma_Z)");
  sub.add_option("--friction", o->friction,
                 "friction angle for the stereonet's sliding overlay, degrees (default 30)");
  return [o] { return run(*o); };
}

const VerbRegistrar reg{"measure", "measure traces, areas and points picked on a 3D image",
                        setup_measure};

}  // namespace
}  // namespace rockface::app
