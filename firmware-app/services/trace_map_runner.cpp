// The Mapping screen's blocks (issue 28): the visit as the analysis reads it
// (storage::load_scene_source, the same scene the Blocks screen analyses),
// through one MapVerdictSession kept while the visit and everything but its
// traces stay the same, so that an edit recomputes only what it touched.
#include <mutex>
#include <sstream>

#include "firmware-app/analysis/analysis_input.h"
#include "firmware-app/analysis/map_verdicts.h"
#include "firmware-app/services/ui_services.h"
#include "storage/export_scene_json.h"
#include "storage/project_store.h"
#include "storage/scene.h"

namespace rockface::app {

namespace {

// What a MapVerdictSession is built from (map_verdicts.h), exactly: the
// surface, the datum, the map's tolerances, the rock and the effects. The
// preset and the other analysis options do not enter the map's verdicts, so
// an analysis saved in between (which names its preset) keeps the session.
std::string session_key(const AnalysisInput& input, const nlohmann::json& scene) {
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

struct StoreTraceMapRunner::Cache {
  std::mutex mutex;
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
  const AnalysisInput input = analysis_input(scene);
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

}  // namespace rockface::app
