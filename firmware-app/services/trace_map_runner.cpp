// The Mapping screen's blocks (issue 28): the visit as the analysis reads it
// (storage::load_scene_source, the same scene the Blocks screen analyses),
// through one MapVerdictSession kept while the visit and everything but its
// traces stay the same, so that an edit recomputes only what it touched.
// Issue 27: the edits of the map (a trace saved or taken back, the face
// outlined) are stored here too, as `rockface measure` stores picks, with
// the visit's joint table remade from its traces as the verb makes it.
#include <mutex>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/measure/facets/facet_options.h"
#include "core/measure/outline_pieces.h"
#include "core/measure/pick_measurement.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "firmware-app/analysis/map_verdicts.h"
#include "firmware-app/analysis/scene_input.h"
#include "firmware-app/measure/measure_records.h"
#include "firmware-app/measure/visit_trace_joints.h"
#include "firmware-app/records/project_mesh.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "storage/scene/face_outline_words.h"
#include "storage/scene/scene.h"
#include "ui/widgets/format.h"

namespace rockface::app {

namespace {

// What a MapVerdictSession is built from (map_verdicts.h), exactly: the
// surface, the datum, the map's tolerances, the rock and the effects. The
// preset and the other analysis options do not enter the map's verdicts, so
// an analysis saved in between (which names its preset) keeps the session.
std::string session_key(const analysis::AnalysisInput& input, const nlohmann::json& scene) {
  std::ostringstream key;
  key << std::hexfloat << input.datum.transpose() << ' ' << input.has_datum << ' ' << input.density
      << ' ' << input.gravity.transpose() << ' ' << input.analysis.snap_tolerance << ' '
      << input.analysis.orientation_uncertainty_deg;
  for (const auto& p : input.patches) {
    key << '|' << p.id;
    for (const auto& x : p.polygon) key << ' ' << x.transpose();
  }
  if (scene.contains("effects") && !scene["effects"].empty()) key << '|' << scene["effects"].dump();
  return key.str();
}

}  // namespace

// A pair's 3D image loaded from the store, for measuring its traces.
struct LoadedPicker {
  photogrammetry::SurfaceMesh surface;
  std::unique_ptr<measure::MeshPicker> picker;  // points into `surface`
};

struct StoreTraceMapRunner::Cache {
  std::mutex mutex;
  // The visit's other pairs' 3D images (issue 27: each trace is measured on
  // its own pair's), by project and model, loaded once.
  std::map<std::pair<std::filesystem::path, storage::RecordId>, std::unique_ptr<LoadedPicker>>
      pickers;
  std::filesystem::path project;
  storage::RecordId visit_id = 0;
  std::string key;  // the scene without its traces: what the session was built for
  std::unique_ptr<MapVerdictSession> session;
};

StoreTraceMapRunner::StoreTraceMapRunner() : cache_(new Cache) {}
StoreTraceMapRunner::~StoreTraceMapRunner() = default;

ui::MapVerdicts StoreTraceMapRunner::update(const std::filesystem::path& project,
                                            storage::RecordId visit_id, Progress& progress) {
  std::lock_guard<std::mutex> lock(cache_->mutex);
  progress.step("reading the traces", 0.05);
  storage::ProjectStore store = storage::ProjectStore::open(project);
  const storage::SceneSource source = storage::load_scene_source(store, visit_id);
  const nlohmann::json json = storage::make_scene_json(source);
  const storage::Scene scene = storage::parse_scene(
      json.dump(), project.filename().string() + " visit " + std::to_string(visit_id));
  const analysis::AnalysisInput input = analysis_input(scene);
  std::string key = session_key(input, json);
  if (!cache_->session || cache_->project != project || cache_->visit_id != visit_id ||
      cache_->key != key) {
    cache_->session.reset();
    cache_->session = std::make_unique<MapVerdictSession>(input);
    cache_->project = project;
    cache_->visit_id = visit_id;
    cache_->key = std::move(key);
  }
  progress.step("updating the blocks", 0.2);
  return cache_->session->update(input, progress);
}

namespace {

// A joint this runner (or `rockface measure`) made of one trace: remade
// from the traces at every edit. Other joints (the scene's, a joint fitted
// to several traces by `rockface replay`, one typed in) are the
// geologist's and stay as they are.
bool made_of_one_trace(const storage::Joint& j) {
  return j.type == "trace" &&
         (j.source == "trace " + j.label || j.source == "trace " + j.label + " (compass)");
}

// The traces a joint that stays was fitted from ("traces T1 T2"): they have
// their joint already.
std::set<std::string> traces_named_by(const storage::Joint& j) {
  std::set<std::string> out;
  std::istringstream words(j.source);
  std::string word;
  words >> word;
  if (word != "trace" && word != "traces") return out;
  while (words >> word) out.insert(word);
  return out;
}

bool same_joint(const storage::Joint& a, const storage::Joint& b) {
  return a.label == b.label && a.set_label == b.set_label && a.dip_deg == b.dip_deg &&
         a.dipdir_deg == b.dipdir_deg && a.point == b.point &&
         a.measurement_id == b.measurement_id && a.source == b.source && a.type == b.type &&
         a.persistence_m == b.persistence_m;
}

bool same_set(const storage::JointSet& a, const storage::JointSet& b) {
  return a.label == b.label && a.dip_deg == b.dip_deg && a.dipdir_deg == b.dipdir_deg &&
         a.fisher_k == b.fisher_k && a.count == b.count && a.alpha95_deg == b.alpha95_deg &&
         a.spacing_m == b.spacing_m && a.mean_trace_length_m == b.mean_trace_length_m &&
         a.censored_traces == b.censored_traces && a.persistence_m == b.persistence_m;
}

// The visit's joint table remade from its stored traces (visit_trace_joints.h):
// the one-trace joints and the sets replaced where they changed (a row
// that stays the same is not rewritten, so the office gets only the
// change). Returns the joint of `trace` in words, or why it has none.
std::string remake_trace_joints(
    storage::ProjectStore& store, storage::RecordId visit, const measure::MeshPicker& picker,
    const std::map<storage::RecordId, const measure::MeshPicker*>& pickers,
    const measure::MeasureSettings& settings, const std::string& trace) {
  const auto old_joints = store.list_joints(visit);
  const auto old_sets = store.list_joint_sets(visit);
  std::set<std::string> covered, kept_labels;
  bool kept_name_sets = false;
  for (const auto& j : old_joints)
    if (!made_of_one_trace(j)) {
      const auto named = traces_named_by(j);
      covered.insert(named.begin(), named.end());
      kept_labels.insert(j.label);
      kept_name_sets = kept_name_sets || !j.set_label.empty();
    }
  std::vector<storage::Measurement> traces;
  for (const auto& m : store.list_measurements(visit))
    if (m.kind == storage::Measurement::Kind::trace && !covered.count(m.label)) traces.push_back(m);
  TraceJointTable table = trace_joint_table(traces, picker, settings, visit, pickers);
  std::vector<storage::Joint> joints;
  for (auto& j : table.joints) {
    if (kept_labels.count(j.label)) {
      table.without_joint.push_back(j.label + ": the visit has a joint " + j.label + " already");
      continue;
    }
    // Sets that other joints name are the geologist's: left as they are,
    // and the traces' joints join none.
    if (kept_name_sets) j.set_label.clear();
    joints.push_back(std::move(j));
  }
  std::vector<storage::JointSet> sets = kept_name_sets ? old_sets : table.sets;
  bool sets_changed = sets.size() != old_sets.size();
  for (std::size_t k = 0; !sets_changed && k < sets.size(); ++k)
    sets_changed = !same_set(sets[k], old_sets[k]);
  // What goes: the one-trace joints that changed (all of them when the sets
  // change: they name the sets' rows), and the changed sets.
  std::vector<storage::RecordId> joints_going, sets_going;
  std::vector<storage::Joint> joints_coming;
  for (const auto& old : old_joints) {
    if (!made_of_one_trace(old)) continue;
    const bool stays =
        !sets_changed && std::any_of(joints.begin(), joints.end(),
                                     [&](const storage::Joint& j) { return same_joint(j, old); });
    if (!stays) joints_going.push_back(old.id);
  }
  for (const auto& j : joints) {
    const bool there =
        !sets_changed && std::any_of(old_joints.begin(), old_joints.end(),
                                     [&](const storage::Joint& old) { return same_joint(j, old); });
    if (!there) joints_coming.push_back(j);
  }
  if (sets_changed)
    for (const auto& s : old_sets) sets_going.push_back(s.id);
  if (!joints_going.empty() || !sets_going.empty())
    store.delete_joints(visit, joints_going, sets_going);
  if (!joints_coming.empty() || sets_changed)
    store.save_joints(visit, sets_changed ? sets : std::vector<storage::JointSet>{}, joints_coming);

  if (trace.empty()) return {};
  for (const auto& j : joints)
    if (j.label == trace) {
      std::string said = "joint " + j.label + " " +
                         ui::format::dip_and_direction(j.dip_deg, j.dipdir_deg) +
                         (j.set_label.empty() ? std::string() : " in set " + j.set_label);
      // Issue 27: a plane read with a compass says so, and a trace that
      // leaves it beyond the tolerance says to check the reading.
      if (made_of_one_trace(j) && j.source != "trace " + j.label) {
        said += " (compass)";
        for (const auto& m : traces)
          if (m.label == trace && m.compass_off_deg &&
              *m.compass_off_deg > measure::kMaxTraceOffCompassDeg)
            said += ": " + m.note;
      }
      return said;
    }
  for (const auto& w : table.without_joint)
    if (w.rfind(trace + ": ", 0) == 0) return "no joint (" + w.substr(trace.size() + 2) + ")";
  return "no joint";
}

// The face outline (a mapped surface) of the visit: its areas that are no
// free face and that no joint was measured from.
std::vector<storage::Measurement> face_outlines(storage::ProjectStore& store,
                                                storage::RecordId visit) {
  std::set<std::string> joint_areas;
  for (const auto& j : store.list_joints(visit))
    if (j.type == "area") joint_areas.insert(j.source.substr(j.source.find(' ') + 1));
  std::vector<storage::Measurement> out;
  for (const auto& m : store.list_measurements(visit))
    if (m.kind == storage::Measurement::Kind::area && m.rock_side.empty() &&
        !joint_areas.count(m.label))
      out.push_back(m);
  return out;
}

std::string next_label(storage::ProjectStore& store, storage::RecordId visit, char letter) {
  int n = 0;
  for (const auto& m : store.list_measurements(visit))
    if (m.label.size() > 1 && m.label[0] == letter) n = std::max(n, std::atoi(m.label.c_str() + 1));
  return std::string(1, letter) + std::to_string(n + 1);
}

// The outline measured and stored as `rockface measure` measures and
// stores area picks (measurement_records), as the flat pieces of the 3D
// image it covers (core/measure/outline_pieces.h: a folded face is several
// planes, and the analysis snaps traces onto its patches within
// centimetres): one area row per piece, F1a, F1b, ... (a flat face: one
// row, F1). What the split says in words (a part too small or too rough to
// be a plane) is kept in the largest piece's note.
std::vector<storage::Measurement> outline_records(const ui::MapEdit& edit,
                                                  const measure::MeasureSettings& settings,
                                                  const measure::FacetOptions& options,
                                                  const std::string& label, double& area_m2) {
  const std::string where = "face outline";
  if (edit.outline.size() < 3)
    throw InputError(where, "needs 3 or more corners, got " + std::to_string(edit.outline.size()));
  if (!edit.view) throw InputError(where, "no photograph's camera to measure it from");
  // The pieces held to the analysis' default snap tolerance (the scene the
  // visit exports leaves it at its default).
  measure::OutlinePieces split =
      measure::split_outline(*edit.picker, *edit.view, label, edit.outline, settings, options,
                             analysis::SceneAnalysis{}.snap_tolerance, where);
  std::string& said = split.pieces.front().plane.problem;
  for (const auto& note : split.notes) said += (said.empty() ? "" : "; ") + note;
  measure::MeasuredPicks picks;
  area_m2 = 0;
  for (auto& a : split.pieces) {
    area_m2 += a.area;
    // A mapped surface, not a free face: no rock side (the analysis takes
    // each piece as a patch of the face, SCENE.md surface.patches).
    picks.areas.push_back({std::move(a), ""});
  }
  return measurement_records(picks, edit.visit_id,
                             {edit.outline_model_id, edit.outline_capture_id});
}

// The preset the visit's first pair was reconstructed with (standard when
// none is stored).
Preset visit_preset(storage::ProjectStore& store, storage::RecordId visit) {
  const auto models = store.list_visit_models(visit);
  return models.empty() || models.front().preset.empty()
             ? Preset::standard
             : parse_preset(models.front().preset, "model " + std::to_string(models.front().id));
}

// The settings `rockface measure` measures the visit with
// (measure_models.cpp): the point precision the screen has (the
// reconstruction's), and the correlation length of the first pair's model
// (its mesh's edge times its preset's matching window).
measure::MeasureSettings measure_settings(storage::ProjectStore& store, storage::RecordId visit,
                                          const ui::MapEdit& edit) {
  measure::MeasureSettings settings = edit.settings;
  const Preset preset = visit_preset(store, visit);
  settings.correlation_length = edit.picker->mesh().median_edge_length() *
                                photogrammetry::reconstruction_preset(preset).sgbm_block_size;
  return settings;
}

// The 3D image of each pair whose traces the visit holds, by model id: the
// one on display for its own model, the others loaded from the store once.
std::map<storage::RecordId, const measure::MeshPicker*> visit_pickers(
    storage::ProjectStore& store, storage::RecordId visit, const ui::MapEdit& edit,
    const std::filesystem::path& project,
    std::map<std::pair<std::filesystem::path, storage::RecordId>, std::unique_ptr<LoadedPicker>>&
        cache) {
  std::map<storage::RecordId, const measure::MeshPicker*> out;
  if (edit.model_id) out[*edit.model_id] = edit.picker;
  for (const auto& m : store.list_measurements(visit)) {
    if (m.kind != storage::Measurement::Kind::trace || !m.model_id || out.count(*m.model_id))
      continue;
    auto& loaded = cache[{project, *m.model_id}];
    if (!loaded) {
      loaded = std::make_unique<LoadedPicker>();
      // As the tablet's model view picks on it: the stored mesh, whole.
      loaded->surface = surface_mesh(store.load_model(*m.model_id).mesh, 0, 0);
      loaded->picker = std::make_unique<measure::MeshPicker>(loaded->surface);
    }
    out[*m.model_id] = loaded->picker.get();
  }
  return out;
}

// The 3D image a stored trace lies on: its pair's.
const measure::MeshPicker& picker_of_trace(
    const storage::Measurement& m, const ui::MapEdit& edit,
    const std::map<storage::RecordId, const measure::MeshPicker*>& pickers) {
  if (m.model_id)
    if (const auto p = pickers.find(*m.model_id); p != pickers.end() && p->second)
      return *p->second;
  return *edit.picker;
}

std::string area_words(double m2) {
  return format_fixed(m2, 1, " m²");
}

}  // namespace

std::string StoreTraceMapRunner::store(const std::filesystem::path& project,
                                       const ui::MapEdit& edit, Progress& progress) {
  if (!edit.picker) throw InputError("map edit", "no 3D image on display to measure on");
  std::lock_guard<std::mutex> lock(cache_->mutex);
  progress.step("storing", 0.05);
  storage::ProjectStore store = storage::ProjectStore::open(project);
  if (store.read_only())
    throw InputError(project.filename().string(), "cannot store: " + store.read_only_reason());
  const storage::RecordId visit = edit.visit_id;
  const measure::MeasureSettings settings = measure_settings(store, visit, edit);
  std::vector<std::string> said;
  std::string trace;  // the trace whose joint is told
  const auto pickers = visit_pickers(store, visit, edit, project, cache_->pickers);
  if (!edit.outline.empty()) {
    // Checked and measured before anything is deleted: a refused outline
    // leaves the stored one.
    const std::string label = next_label(store, visit, 'F');
    double area = 0;
    // The facet finder's knobs of the visit's preset: its angle, its
    // smallest facet and its planarity gate judge the pieces too.
    const std::vector<storage::Measurement> records = outline_records(
        edit, settings, measure::facet_options(visit_preset(store, visit)), label, area);
    for (const auto& old : face_outlines(store, visit)) store.delete_measurement(old.id);
    store.save_measurements(visit, records);
    said.push_back(storage::face_outline_words(records, {}).front() + "; " +
                   std::to_string(edit.outline.size()) + " corners, " + area_words(area) +
                   " stored");
  }
  if (edit.remove_trace) {
    std::string label;
    for (const auto& m : store.list_measurements(visit))
      if (m.id == *edit.remove_trace && m.kind == storage::Measurement::Kind::trace)
        label = m.label;
    if (label.empty())
      throw InputError("trace " + std::to_string(*edit.remove_trace),
                       "no such trace in visit " + std::to_string(visit));
    store.delete_measurement(*edit.remove_trace);
    said.push_back("trace " + label + " and its joint removed");
  }
  if (edit.compass_trace) {
    // Issue 27: a saved trace's compass reading given or cleared: the trace
    // measured again with it (as `rockface measure` would with the reading
    // in its picks), in place; its joint is remade below.
    std::optional<storage::Measurement> stored;
    for (const auto& m : store.list_measurements(visit))
      if (m.id == *edit.compass_trace && m.kind == storage::Measurement::Kind::trace) stored = m;
    if (!stored)
      throw InputError("trace " + std::to_string(*edit.compass_trace),
                       "no such trace in visit " + std::to_string(visit));
    storage::Measurement tapped = *stored;
    tapped.compass_dip_deg.reset();
    tapped.compass_dipdir_deg.reset();
    if (edit.compass) {
      tapped.compass_dip_deg = edit.compass->dip_deg;
      tapped.compass_dipdir_deg = edit.compass->dip_direction_deg;
    }
    const storage::Measurement measured =
        measured_trace_record(tapped, picker_of_trace(*stored, edit, pickers), settings);
    store.set_trace_plane(stored->id, measured);
    trace = stored->label;
    said.push_back(edit.compass ? "compass reading of " + trace + " saved"
                                : "compass reading of " + trace + " cleared");
  }
  if (edit.trace) {
    storage::Measurement record = measured_trace_record(*edit.trace, *edit.picker, settings);
    record.visit_id = visit;
    store.save_measurements(visit, {record});
    trace = record.label;
    said.push_back("trace " + record.label + " saved");
  }
  progress.step("remaking the joints", 0.5);
  const std::string joint =
      remake_trace_joints(store, visit, *edit.picker, pickers, settings, trace);
  if (!joint.empty()) said.back() += ": " + joint;
  std::string out;
  for (const auto& s : said) out += (out.empty() ? "" : "; ") + s;
  return out;
}

}  // namespace rockface::app
