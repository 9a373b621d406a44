#include "firmware-app/measure/measure_workflow.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/pair_photo.h"
#include "core/measure/stereonet_image.h"
#include "firmware-app/measure/measure_records.h"
#include "firmware-app/measure/measures_json.h"
#include "storage/exchange/export_joints_csv.h"
#include "storage/exchange/image_file.h"
#include "storage/project/project_store.h"
#include "storage/scene/picks_json.h"

namespace rockface::app {

namespace {

namespace fs = std::filesystem;

// Every pick names a pair the 3D images have.
void check_pairs(const measure::Picks& picks, const MeasureRequest& r, const ProjectPairs& pairs) {
  const std::size_t n = pairs.models.size();
  auto check = [&](const std::string& where, int pair) {
    if (static_cast<std::size_t>(pair) <= n) return;
    throw InputError(
        r.picks + ": " + where + ".pair",
        "pair " + std::to_string(pair) + ", but " + pairs.what + " of " + r.on.source + " has " +
            std::to_string(n) + (n == 1 ? " pair" : " pairs") +
            (r.on.model ? " (--model measures one 3D image; --visit measures a visit's "
                          "pairs)"
                        : ""));
  };
  for (const auto& t : picks.traces) check(t.where, t.pair);
  for (const auto& a : picks.areas) check(a.where, a.pair);
  for (const auto& p : picks.points) check(p.where, p.pair);
}

cv::Mat stereonet(const measure::MeasuredPicks& r, const std::string& title, double friction_deg) {
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

// --add-to-visit: the visit is there and has a 3D image to measure on,
// said with its name (what started it) before anything is measured.
void check_visit_to_add_to(storage::ProjectStore& store, const MeasureRequest& r) {
  const auto visits = store.list_visits();
  const auto it = std::find_if(visits.begin(), visits.end(),
                               [&](const storage::Visit& v) { return v.id == *r.on.visit; });
  if (it == visits.end())
    throw InputError("--add-to-visit",
                     "no visit " + std::to_string(*r.on.visit) + " in " + r.on.source);
  if (store.list_visit_models(it->id).empty())
    throw InputError("--add-to-visit", "visit " + std::to_string(it->id) + " (" + it->source +
                                           ") of " + r.on.source +
                                           " has no 3D image to measure on: reconstruct its "
                                           "pairs first, or measure on a visit that has one");
}

// --add-to-visit: no label the visit already holds is stored again (the
// store keeps one of each per visit); checked before anything is stored.
void check_new_labels(storage::ProjectStore& store, storage::RecordId visit,
                      const std::string& picks, const std::vector<storage::Measurement>& records,
                      const std::vector<storage::JointSet>& sets,
                      const std::vector<storage::Joint>& joints) {
  std::set<std::string> held;
  for (const auto& m : store.list_measurements(visit)) held.insert("measurement " + m.label);
  for (const auto& j : store.list_joints(visit)) held.insert("joint " + j.label);
  for (const auto& s : store.list_joint_sets(visit)) held.insert("joint set " + s.label);
  std::vector<std::string> adding;
  for (const auto& m : records) adding.push_back("measurement " + m.label);
  for (const auto& j : joints) adding.push_back("joint " + j.label);
  for (const auto& s : sets) adding.push_back("joint set " + s.label);
  for (const auto& a : adding)
    if (held.count(a))
      throw InputError(picks, "visit " + std::to_string(visit) + " already holds a " + a +
                                  ": give the pick another id, or measure into a new visit "
                                  "(without --add-to-visit); nothing was stored");
}

}  // namespace

MeasureOutcome measure_picks_file(const MeasureRequest& r) {
  if (!fs::exists(r.on.source)) throw InputError(r.on.source, "no such file");
  const measure::Picks picks = storage::load_picks(r.picks);
  std::optional<int> sets = r.sets;
  if (!sets) sets = r.automatic_sets ? std::nullopt : picks.sets;

  const bool ply = fs::path(r.on.source).extension() == ".ply";
  std::optional<storage::ProjectStore> store;
  LoadedModel model;                 // pair 1: its mesh frame is the face frame
  std::vector<LoadedModel> further;  // the further pairs the picks use (pair 2, 3, ...)
  std::string on;                    // what was measured on, for the visit's note
  if (ply) {
    // A model file is one 3D image: pair 1 only.
    check_pairs(picks, r, {{0}, "the model file"});
    model = load_ply_model(r.on);
  } else {
    store.emplace(storage::ProjectStore::open(r.on.source));
    if (store->read_only())
      throw InputError(r.on.source,
                       "cannot store measurements in it: " + store->read_only_reason());
    if (r.add_to_visit) check_visit_to_add_to(*store, r);
    const ProjectPairs pairs = project_pairs(*store, r.on);
    check_pairs(picks, r, pairs);
    std::set<int> used;
    for (const auto& t : picks.traces) used.insert(t.pair);
    for (const auto& a : picks.areas) used.insert(a.pair);
    for (const auto& p : picks.points) used.insert(p.pair);
    model = load_stored_model(*store, r.on, pairs.models[0], 1);
    on = pairs.what + ": model " + std::to_string(pairs.models[0]);
    for (const int pair : used)
      if (pair > 1) {
        further.push_back(load_stored_model(*store, r.on, pairs.models[pair - 1], pair));
        on += ", model " + std::to_string(pairs.models[pair - 1]) + " (pair " +
              std::to_string(pair) + ")";
      }
  }
  const measure::MeshPicker picker(model.mesh);
  std::deque<measure::MeshPicker> further_pickers;  // the context refers to them
  measure::MeasureContext context;
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
  context.source = r.picks;
  MeasureOutcome outcome;
  outcome.measured = measure::measure_picks(measure::picks_by_pair_photo(picks), context, sets);
  const measure::MeasuredPicks& measured = outcome.measured;

  // Everything measured: now the store (one visit, each save one
  // transaction) and the outputs.
  // Pieces of one joint trace measured on different pairs are one trace
  // (joined by measure_picks, as the replay joins them).
  const std::vector<measure::JoinedTrace>& joined = measured.joined;
  std::vector<storage::Joint> joints = joint_records(measured, 0);
  join_trace_joints(joined, joints);
  // The joints the traces name, fitted to all their traces (as the replay
  // stores them): without them the visit's traces name joints it lacks.
  try {
    add_named_joints(measured, 0, joints);
  } catch (const InputError& e) {
    throw InputError(r.picks + ": " + e.where(), e.reason());  // the picks file named
  }
  if (store) {
    // A named joint with no plane is said in the visit's note, by name.
    std::string note = "picks measured on " + on;
    for (const auto& j : measured.joints)
      if (!j.plane.known) note += "; joint " + j.label + ": " + j.plane.problem;
    std::map<std::string, PairRecords> further_records;
    for (const auto& f : further)
      for (const auto& [name, view] : f.views) further_records[name] = {f.model_id, f.capture_id};
    // The visit id is set on the records once the visit is known.
    auto records =
        measurement_records(measured, 0, {model.model_id, model.capture_id}, further_records);
    join_trace_records(joined, records);
    unname_joints_without_plane(measured, records);
    const std::vector<storage::JointSet> sets = joint_set_records(measured);
    if (r.add_to_visit) check_new_labels(*store, *r.on.visit, r.picks, records, sets, joints);
    const storage::RecordId visit =
        r.add_to_visit ? *r.on.visit : store->begin_visit("measure " + r.picks, note, r.geologist);
    for (auto& m : records) m.visit_id = visit;
    const auto ids = store->save_measurements(visit, records);
    for (auto& j : joints) {
      j.visit_id = visit;
      for (std::size_t k = 0; k < records.size(); ++k)
        if (records[k].label == j.label) j.measurement_id = ids[k];
    }
    store->save_joints(visit, sets, joints);
    outcome.visit = visit;
    if (r.stored) r.stored(visit);
  }
  const cv::Mat png =
      r.png.empty() ? cv::Mat()
                    : stereonet(measured, fs::path(r.picks).filename().string(), r.friction_deg);
  std::map<std::string, std::string> further_models;
  for (const auto& f : further)
    for (const auto& [name, view] : f.views) further_models[name] = f.name;
  write_text_atomically(r.out, measures_json(measured, context, model.name, further_models));
  if (!png.empty()) storage::write_image_file(r.png, png);
  if (!r.csv.empty()) {
    std::ostringstream csv;
    storage::write_joints_csv(csv, joints, model.datum);
    write_text_atomically(r.csv, csv.str());
  }
  return outcome;
}

}  // namespace rockface::app
