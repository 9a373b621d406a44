#include "firmware-app/wedges/wedges_workflow.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/analysis/analysis_input.h"
#include "core/common/error.h"
#include "firmware-app/records/project_visit.h"
#include "firmware-app/wedges/support_options.h"

namespace rockface::app {

namespace {

bool looks_like_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c))
    if (!std::isspace(static_cast<unsigned char>(c))) return c == '{';
  return false;
}

}  // namespace

WedgesResult wedges_from_input(const WedgesRequest& q) {
  if (!std::filesystem::exists(q.input)) throw InputError(q.input, "no such file");
  std::optional<std::pair<double, double>> axis;
  if (q.axis) axis = parse_axis(*q.axis, "--axis");
  WedgesResult out;
  if (looks_like_json(q.input)) {
    for (auto [given, name] : {std::pair{q.friction_deg.has_value(), "--friction"},
                               std::pair{q.cohesion_pa.has_value(), "--cohesion"},
                               std::pair{q.trace_length_m.has_value(), "--trace-length"},
                               std::pair{q.bolts.has_value(), "--bolts"},
                               std::pair{q.shotcrete.has_value(), "--shotcrete"},
                               std::pair{q.visit.has_value(), "--visit"}})
      if (given)
        throw InputError(name, "applies to a project; a scene gives it in its wedges section");
    storage::Scene scene = storage::load_scene(q.input);
    if (q.preset) scene.analysis.preset = parse_preset(*q.preset, "--preset");
    out.run = wedge_run_from_scene(scene, axis);
  } else {
    storage::OpenOptions read;
    read.read_only = true;
    storage::ProjectStore store = storage::ProjectStore::open(q.input, read);
    const auto visit = q.visit ? q.visit : store.latest_visit();
    if (!visit) throw InputError(q.input, "the project has no visit");
    if (q.visit) require_visit(store, *q.visit);
    ProjectWedgeSettings s;
    s.axis = axis;
    if (q.friction_deg) {
      if (!(*q.friction_deg >= 0 && *q.friction_deg < 90))
        throw InputError("--friction", "must be in [0, 90) degrees");
      s.friction_deg = *q.friction_deg;
      s.friction_given = true;
    }
    if (q.cohesion_pa) {
      if (!(*q.cohesion_pa >= 0 && *q.cohesion_pa <= analysis::kMaxJointCohesionPa))
        throw InputError("--cohesion", "must be in [0, 1e8] Pa (a joint's cohesion)");
      s.cohesion_pa = *q.cohesion_pa;
    }
    if (q.trace_length_m) {
      if (!(*q.trace_length_m > 0)) throw InputError("--trace-length", "must be positive (m)");
      s.trace_length = q.trace_length_m;
    }
    if (q.bolts) s.bolts = parse_pattern_bolts(*q.bolts, "--bolts");
    if (q.shotcrete) s.shotcrete = parse_shotcrete(*q.shotcrete, "--shotcrete");
    if (q.preset) s.preset = parse_preset(*q.preset, "--preset");
    out.run = wedge_run_from_project(store, *visit, s);
  }
  try {
    out.analysis = run_wedges(out.run);
  } catch (const InputError& e) {
    throw InputError(out.run.source, e.what());
  }
  return out;
}

std::optional<WedgesResult> project_visit_wedges(storage::ProjectStore& store,
                                                 storage::RecordId visit, std::string* why) {
  try {
    WedgesResult out;
    out.run = wedge_run_from_project(store, visit, {});
    out.analysis = run_wedges(out.run);
    return out;
  } catch (const InputError& e) {
    if (why) *why = e.what();
    return std::nullopt;
  }
}

}  // namespace rockface::app
