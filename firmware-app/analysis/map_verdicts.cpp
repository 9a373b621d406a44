#include "firmware-app/analysis/map_verdicts.h"

#include <chrono>

#include "core/analysis/scene_effects.h"
#include "core/analysis/trace_map_input.h"
#include "core/common/error.h"
#include "core/common/units.h"
#include "core/faces/trace_session.h"
#include "core/kinematics/sliding_mode.h"

namespace rockface::app {

struct MapVerdictSession::State {
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  // Declared before the session: its options point at them.
  kinematics::Effects effects;
  std::unique_ptr<faces::TraceSession> session;
};

MapVerdictSession::MapVerdictSession(const analysis::AnalysisInput& input) : state_(new State) {
  if (input.patches.empty())
    throw InputError(input.source + ": surface.patches",
                     "the visit has no surface patches (mark the face's outline first); blocks "
                     "from traces need the free surface");
  const analysis::TraceMapInput map = analysis::trace_map_input(input);
  state_->datum = map.datum;
  state_->effects = analysis::scene_effects(input);
  faces::TraceBlockOptions options;
  options.snap_tolerance = map.snap_tolerance;
  options.orientation_uncertainty = map.orientation_uncertainty;
  options.density = input.density;
  options.effects = &state_->effects;
  options.datum = map.datum;
  try {
    state_->session = std::make_unique<faces::TraceSession>(
        map.patches, faces::NetworkOptions{map.snap_tolerance, map.orientation_uncertainty},
        options);
  } catch (const InputError& e) {
    throw InputError(input.source + ": " + e.where(), e.reason());
  }
}

MapVerdictSession::~MapVerdictSession() = default;

ui::MapVerdicts MapVerdictSession::update(const analysis::AnalysisInput& input,
                                          Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const analysis::TraceMapInput map = analysis::trace_map_input(input);
  const std::vector<faces::TraceBlock>* blocks = nullptr;
  try {
    blocks = &state_->session->update(map.traces, progress);
  } catch (const InputError& e) {
    throw InputError(input.source + ": " + e.where(), e.reason());
  }
  ui::MapVerdicts out;
  out.traces = static_cast<int>(map.traces.size());
  out.recomputed = state_->session->recomputed();
  out.reused = state_->session->reused();
  for (const auto& n : state_->session->network().notes()) out.notes.push_back(n);
  for (const auto& b : *blocks) {
    // The verdict as the Blocks screen decides it from the stored block
    // (field_records: marginal is finiteness or removability marginal).
    analysis::ReportBlock r;
    r.finite = b.finite;
    r.removable = b.finiteness.removable.value;
    r.marginal = b.finiteness.removable.marginal || b.finiteness.finite.marginal;
    if (b.analysis && b.analysis->mode) {
      r.mode = analysis::ReportMode{};
      r.mode->type = kinematics::mode_name(b.analysis->mode->type);
      r.fos = b.analysis->fos;
    }
    ui::MapBlock m;
    for (const auto& x : b.surface_polygon) m.outline.push_back(x + state_->datum);
    m.verdict = analysis::verdict_of(r);
    m.mode = r.mode ? r.mode->type : "none";
    m.factor_of_safety = r.fos;
    m.margin_deg =
        rad_to_deg(b.finite ? b.finiteness.removable.margin : b.finiteness.finite.margin);
    if (b.analysis) m.volume_m3 = b.analysis->mass.volume;
    out.blocks.push_back(std::move(m));
  }
  out.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rockface::app
