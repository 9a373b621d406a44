#include "core/analysis/scene_analysis.h"

#include <chrono>

#include "core/analysis/analyse_rock_mass.h"

namespace rockface::analysis {

namespace {

template <class F>
double timed_ms(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Report analyse(const AnalysisInput& scene, Progress& progress) {
  Report report;
  report.effects_simulated = scene.effects.listed();
  // Which analyses run: geometry always; limit equilibrium unless the
  // scene says "none"; the equilibrium path only when asked for.
  if (scene.analysis.stability != "none") report.analyses.push_back("limit_equilibrium");
  if (scene.analysis.stability == "equilibrium_path") report.analyses.push_back("equilibrium_path");
  // Geometric checks are cheap and always run when the scene has the input.
  if (scene.analysis.pyramids && !scene.joints.empty() && !scene.free_faces.empty()) {
    progress.step("joint pyramids", 0.0);
    report.timings_ms["pyramids"] = timed_ms([&] { analyse_pyramids(scene, report); });
  }
  if (scene.analysis.blocks && !scene.blocks.empty()) {
    progress.step("blocks", 0.3);
    report.timings_ms["blocks"] = timed_ms([&] { analyse_scene_blocks(scene, report, progress); });
  }
  if (scene.analysis.blocks && !scene.traces.empty()) {
    progress.step("trace map", 0.6);
    report.timings_ms["traces"] = timed_ms([&] { analyse_trace_blocks(scene, report, progress); });
  }
  // The trace map's rock mass (spacing, RQD, Jv, block sizes, RMR89 / Q):
  // whenever there are traces, with the scene's rockmass form.
  if (!scene.traces.empty()) {
    progress.step("rock mass", 0.9);
    report.timings_ms["rockmass"] = timed_ms([&] { analyse_rock_mass(scene, report); });
  }
  // Dynamics after failure: listed when a block's motion was simulated.
  if (scene.analysis.dynamics) {
    bool ran = false;
    for (const auto& b : report.blocks) ran = ran || b.dynamics.has_value();
    if (ran)
      report.effects_simulated.push_back("dynamics after failure");
    else
      report.notes.push_back(
          "dynamics after failure: no block fails under its loads, nothing to simulate");
  }
  progress.step("done", 1.0);
  return report;
}

}  // namespace rockface::analysis
