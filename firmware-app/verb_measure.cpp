// `rockface measure MODEL.ply|PROJECT --traces PICKS.json --out MEASURES.json
//  [--png STEREONET.png] [--csv DIPS.csv] [--sets N|auto] [--visit N | --model ID]`
//
// Measures the picks on a 3D image: a model file (with the camera it was
// reconstructed with) or a project's visit, each pick on the 3D image of its
// pair (picks.h `pair`), all in the face frame (the first pair's). Everything
// is measured before anything is written: a bad pick stops the verb (exit 2)
// naming it, with nothing stored and no output file.
#include <algorithm>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/stereonet_image.h"
#include "core/photogrammetry/preset.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/measure_picks.h"
#include "firmware-app/records/project_mesh.h"
#include "storage/camera_json.h"
#include "storage/export_file.h"
#include "storage/export_joints_csv.h"
#include "storage/ply_reader.h"
#include "storage/project_store.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;

struct MeasureOptions {
  std::string source, picks, out, png, csv, sets, camera, photo;
  std::optional<storage::RecordId> model, visit;
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

// One stored model, its photographs named for its pair (pair_photo).
LoadedModel load_stored_model(storage::ProjectStore& store, const MeasureOptions& o,
                              storage::RecordId id, int pair) {
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
  if (!model.camera_to_mesh)
    throw InputError(o.source, "model " + std::to_string(id) +
                                   " keeps no pose of its camera (a further pair stored before "
                                   "schema 4): replay the visit again to measure on it");
  m.capture_id = model.texture_capture_id;
  const storage::Capture capture = store.load_capture(*model.texture_capture_id);
  if (!capture.calibration_id)
    throw InputError(o.source,
                     "the capture of model " + std::to_string(id) + " has no calibration");
  const auto intrinsics = store.load_calibration(*capture.calibration_id).intrinsics;
  const photogrammetry::Similarity& camera_to_mesh = *model.camera_to_mesh;
  auto add_view = [&](measure::PhotoView view, const std::vector<unsigned char>& bytes) {
    const std::string name = pair_photo(pair, view.name);
    view.name = name;
    m.views.emplace(name, std::move(view));
    m.photos[name] = decode(bytes);
  };
  add_view(measure::left_view(camera_to_mesh, intrinsics), capture.left.bytes);
  // The report of the reconstruction: the right camera's relative
  // orientation and the predicted precision of a point.
  const storage::Registration& r = model.registration;
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
    add_view(measure::right_view(camera_to_mesh, R, t, intrinsics), capture.right.bytes);
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

// The 3D images of the project to measure on, one per pair: --model alone,
// else the pairs of --visit or of the newest visit with a model.
struct ProjectPairs {
  std::vector<storage::RecordId> models;
  std::string what;  // "model 3", "visit 2", for messages
};

ProjectPairs project_pairs(storage::ProjectStore& store, const MeasureOptions& o) {
  if (o.model && o.visit)
    throw InputError("--model", "give --model (one 3D image) or --visit (its pairs), not both");
  if (o.model) return {{*o.model}, "model " + std::to_string(*o.model)};
  const auto visits = store.list_visits();
  if (o.visit) {
    if (std::none_of(visits.begin(), visits.end(),
                     [&](const storage::Visit& v) { return v.id == *o.visit; }))
      throw InputError("--visit", "no visit " + std::to_string(*o.visit) + " in " + o.source);
    ProjectPairs out{{}, "visit " + std::to_string(*o.visit)};
    for (const auto& m : store.list_visit_models(*o.visit)) out.models.push_back(m.id);
    if (out.models.empty())
      throw InputError("--visit", "visit " + std::to_string(*o.visit) + " of " + o.source +
                                      " has no model to measure on");
    return out;
  }
  for (auto v = visits.rbegin(); v != visits.rend(); ++v) {
    ProjectPairs out{{}, "visit " + std::to_string(v->id)};
    for (const auto& m : store.list_visit_models(v->id)) out.models.push_back(m.id);
    if (!out.models.empty()) return out;
  }
  throw InputError(o.source, "the project has no model to measure on");
}

// Every pick names a pair the 3D images have.
void check_pairs(const storage::Picks& picks, const MeasureOptions& o, const ProjectPairs& pairs) {
  const std::size_t n = pairs.models.size();
  auto check = [&](const std::string& where, int pair) {
    if (static_cast<std::size_t>(pair) <= n) return;
    throw InputError(o.picks + ": " + where + ".pair",
                     "pair " + std::to_string(pair) + ", but " + pairs.what + " of " + o.source +
                         " has " + std::to_string(n) + (n == 1 ? " pair" : " pairs") +
                         (o.model ? " (--model measures one 3D image; --visit measures a visit's "
                                    "pairs)"
                                  : ""));
  };
  for (const auto& t : picks.traces) check(t.where, t.pair);
  for (const auto& a : picks.areas) check(a.where, a.pair);
  for (const auto& p : picks.points) check(p.where, p.pair);
}

cv::Mat stereonet(const MeasuredPicks& r, const std::string& title, double friction_deg) {
  measure::StereonetPicture pic;
  pic.title = title;
  for (std::size_t k = 0; k < r.poles.size(); ++k) {
    pic.poles.push_back(r.pole_plane(k).fit.normal);
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
  if (!sets) sets = o.sets == "auto" ? std::nullopt : picks.sets;

  const bool ply = fs::path(o.source).extension() == ".ply";
  std::optional<storage::ProjectStore> store;
  LoadedModel model;                 // pair 1: its mesh frame is the face frame
  std::vector<LoadedModel> further;  // the further pairs the picks use (pair 2, 3, ...)
  std::string on;                    // what was measured on, for the visit's note
  if (ply) {
    // A model file is one 3D image: pair 1 only.
    check_pairs(picks, o, {{0}, "the model file"});
    model = load_ply_model(o);
  } else {
    store.emplace(storage::ProjectStore::open(o.source));
    if (store->read_only())
      throw InputError(o.source, "cannot store measurements in it: " + store->read_only_reason());
    const ProjectPairs pairs = project_pairs(*store, o);
    check_pairs(picks, o, pairs);
    std::set<int> used;
    for (const auto& t : picks.traces) used.insert(t.pair);
    for (const auto& a : picks.areas) used.insert(a.pair);
    for (const auto& p : picks.points) used.insert(p.pair);
    model = load_stored_model(*store, o, pairs.models[0], 1);
    on = pairs.what + ": model " + std::to_string(pairs.models[0]);
    for (const int pair : used)
      if (pair > 1) {
        further.push_back(load_stored_model(*store, o, pairs.models[pair - 1], pair));
        on += ", model " + std::to_string(pairs.models[pair - 1]) + " (pair " +
              std::to_string(pair) + ")";
      }
  }
  const measure::MeshPicker picker(model.mesh);
  std::deque<measure::MeshPicker> further_pickers;  // the context refers to them
  MeasureContext context;
  context.picker = &picker;
  context.views = model.views;
  context.photos = model.photos;
  for (const auto& f : further) {
    further_pickers.emplace_back(f.mesh);
    for (const auto& [name, view] : f.views) {
      context.views.emplace(name, view);
      context.pickers[name] = &further_pickers.back();
    }
    for (const auto& [name, photo] : f.photos) context.photos[name] = photo;
  }
  context.settings.point_sigma = model.point_sigma;
  context.settings.correlation_length = model.correlation_length;
  context.datum = model.datum;
  context.source = o.picks;
  const MeasuredPicks measured = measure_picks(picks_by_pair_photo(picks), context, sets);

  // Everything measured: now the store (one visit, each save one
  // transaction) and the outputs.
  // Pieces of one joint trace measured on different pairs are one trace
  // (joined by measure_picks, as the replay joins them).
  const std::vector<JoinedTrace>& joined = measured.joined;
  std::vector<storage::Joint> joints = joint_records(measured, 0);
  join_trace_joints(joined, joints);
  if (store) {
    const storage::RecordId visit =
        store->begin_visit("measure " + o.picks, "picks measured on " + on);
    std::map<std::string, PairRecords> further_records;
    for (const auto& f : further)
      for (const auto& [name, view] : f.views) further_records[name] = {f.model_id, f.capture_id};
    auto records =
        measurement_records(measured, visit, {model.model_id, model.capture_id}, further_records);
    join_trace_records(joined, records);
    const auto ids = store->save_measurements(visit, records);
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
  std::map<std::string, std::string> further_models;
  for (const auto& f : further)
    for (const auto& [name, view] : f.views) further_models[name] = f.name;
  storage::write_text_atomically(o.out,
                                 measures_json(measured, context, model.name, further_models));
  if (!png.empty() && !cv::imwrite(o.png, png)) throw Error(o.png + ": cannot write the picture");
  if (!o.csv.empty()) {
    std::ostringstream csv;
    storage::write_joints_csv(csv, joints, model.datum);
    storage::write_text_atomically(o.csv, csv.str());
  }
  std::size_t known = 0;
  for (const auto& t : measured.traces) known += t.m.plane.known ? 1 : 0;
  std::cout << measured.traces.size() << " traces (" << known << " with a known plane), "
            << measured.areas.size() << " areas, " << measured.points.size() << " points; "
            << measured.sets.size() << " joint sets\n";
  for (const auto& j : joined) std::cout << joined_note(j) << "\n";
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
  sub.add_option("--visit", o->visit,
                 "project: the visit whose 3D images (one per pair; picks name theirs with "
                 "\"pair\") are measured on (default: the newest visit with a model)");
  sub.add_option("--model", o->model, "project: measure on this one model instead (pair 1 only)");
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
