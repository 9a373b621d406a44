// From capture to verdicts (issue 17): the synthetic 24 Mpx tunnel face
// (tools/samples/tunnel-face.scene.json, 6000 x 4000 px, with the remote-axis
// search switched on) from capture to the block table, stage by stage, per
// preset, with peak memory.
//
// Part 1, the field workflow: `rockface replay SCENE --preset P` in a child
// process (face_merge_bench runs the binary the same way). The replay prints one stderr line per
// progress step (core/common/progress.h); each line is timestamped on arrival and the child's peak
// resident set so far (VmHWM of /proc/PID/status) is read with it, so a stage's memory is the
// process peak up to the stage's end. Stages:
//   capture       rendering and spooling the pair (MockCamera), project records
//   features      SIFT on both images, matching, mutual check
//   orientation   relative orientation (essential matrix, pose, refinement,
//                 tie points refined by area matching)
//   dense         rectification, dense matching, triangulation
//   registration  pole / compass registration, saving the model, trace records
//   analysis      `analyse_scene` (pyramids, trace map, blocks, rotation,
//                 remote axis, limit equilibrium) on all cores, saving it
// Counters (seconds, MB): capture_s ... analysis_s, total_s, and *_MB the
// peak after that stage; peak_MB is the child's ru_maxrss (wait4).
//
// Part 2, the verdict stages alone, in this process and on one core: the
// visit the replay stored (its traces, areas and joints, read back through
// storage::load_scene_source and made into the analysis input straight from
// the rows, as the tablet's runners do: storage::visit_analysis_input) made
// into the trace map's input (core/analysis/trace_map_input.h), timed apart:
//   trace_map_ms  free surface, trace network, surface loops
//   blocks_ms     faces::trace_blocks: blocks, finiteness, removability
//   rotation_ms   corner and edge rotatability of the finite blocks
//   remote_ms     remote-axis search (the preset's starts, early stop) of the
//                 finite blocks that cannot rotate about a corner or an edge
//   remote_all_ms the same search on every finite block (no skip)
// Each the fastest of 10 runs (the machine is shared).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "core/analysis/analysis_input.h"
#include "core/analysis/trace_map_input.h"
#include "core/common/preset.h"
#include "core/common/units.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/kinematics/remote_axis.h"
#include "core/kinematics/rotation_input.h"
#include "core/kinematics/rotation_space.h"
#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "tools/bench/replay_child.h"

namespace fs = std::filesystem;
using rockface::bench::Clock;
using rockface::bench::ReplayRun;
using rockface::bench::seconds_since;

namespace {

// The bench's working directory and the scene with the remote-axis search on.
const fs::path& work_dir() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("rockface-verdicts-bench-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face.scene.json");
    nlohmann::json scene = nlohmann::json::parse(in);
    scene["analysis"]["remote_axis"] = true;  // the preset's starts
    std::ofstream(d / "tunnel-face.scene.json") << scene.dump(2);
    return d;
  }();
  return dir;
}

// `rockface replay` of the scene into `project`, its stderr stage lines timed.
ReplayRun run_replay(const std::string& preset, const fs::path& project) {
  return rockface::bench::run_replay(std::string(ROCKFACE_BINARY_DIR) + "/rockface",
                                     (work_dir() / "tunnel-face.scene.json").string(),
                                     project.string(), preset);
}

// The stage a progress line belongs to (see the file comment); "done" (the
// reconstruction's and the analysis's last step) stays in the current one.
std::string stage_of(const std::string& line, const std::string& current) {
  if (line == "done") return current;
  if (line == "capture") return "capture";
  if (line.rfind("features", 0) == 0) return "features";
  if (line.rfind("relative orientation", 0) == 0 || line.rfind("tie points", 0) == 0)
    return "orientation";
  if (line.rfind("rectification", 0) == 0 || line.rfind("dense matching", 0) == 0 ||
      line.rfind("triangulation", 0) == 0)
    return "dense";
  if (line == "registration" || line == "measure") return "registration";
  return "analysis";  // blocks, joint pyramids, trace map, done
}

struct VerdictTimes {
  double trace_map_ms = 0, blocks_ms = 0, rotation_ms = 0, remote_ms = 0;
  double remote_all_ms = 0;
  int blocks = 0, finite = 0, searched = 0, remote_starts = 0, remote_all_starts = 0;
};

// One timed run of the verdict stages on the visit's inputs.
VerdictTimes verdict_stages_once(const std::vector<rockface::faces::PatchInput>& patches,
                                 const std::vector<rockface::faces::TraceInput>& traces,
                                 double density, double tol, double uncertainty,
                                 const Eigen::Vector3d& datum, const std::string& preset) {
  namespace rf = rockface::faces;
  namespace rk = rockface::kinematics;
  VerdictTimes out;
  auto t0 = Clock::now();
  const rf::FreeSurface surface = rf::FreeSurface::build(patches, tol);
  const rf::TraceNetwork net = rf::TraceNetwork::build(surface, traces, {tol, uncertainty});
  const rf::SurfaceLoops loops = rf::SurfaceLoops::find(net, surface);
  out.trace_map_ms = 1000 * seconds_since(t0);

  rf::TraceBlockOptions options;
  options.snap_tolerance = tol;
  options.orientation_uncertainty = uncertainty;
  options.density = density;
  options.datum = datum;
  rockface::NoProgress progress;
  t0 = Clock::now();
  const auto blocks = rf::trace_blocks(surface, net, loops, options, progress);
  out.blocks_ms = 1000 * seconds_since(t0);
  out.blocks = static_cast<int>(blocks.size());

  std::vector<rk::RotationInput> inputs;
  std::vector<rk::RotationAnalysis> rotations;
  t0 = Clock::now();
  for (const auto& b : blocks)
    if (b.finite && b.polyhedron) {
      inputs.push_back(rk::rotation_input(*b.polyhedron));
      rotations.push_back(rk::analyse_rotation(inputs.back(), uncertainty));
    }
  out.rotation_ms = 1000 * seconds_since(t0);
  out.finite = static_cast<int>(inputs.size());

  // As analyse_rotation.cpp: a block that firmly rotates about a corner or an
  // edge is not searched.
  const int starts = rk::remote_axis_starts(rockface::parse_preset(preset, "bench preset"));
  t0 = Clock::now();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    bool has_axis = false;
    for (const auto& c : rotations[i].corners)
      has_axis = has_axis || (c.rotatable.value && !c.rotatable.marginal);
    for (const auto& e : rotations[i].edges)
      has_axis = has_axis || (e.rotatable.value && !e.rotatable.marginal);
    if (has_axis) continue;
    const rk::RemoteAxisResult r = rk::search_remote_axis(inputs[i], {starts, 1, true});
    benchmark::DoNotOptimize(r.found);
    ++out.searched;
    out.remote_starts += r.starts;
  }
  out.remote_ms = 1000 * seconds_since(t0);

  // What the search would cost without the skip: every finite block searched
  // (the preset's starts, early stop as in the report).
  t0 = Clock::now();
  for (const auto& in : inputs) {
    const rk::RemoteAxisResult r = rk::search_remote_axis(in, {starts, 1, true});
    benchmark::DoNotOptimize(r.found);
    out.remote_all_starts += r.starts;
  }
  out.remote_all_ms = 1000 * seconds_since(t0);
  return out;
}

// The visit's trace map analysed stage by stage, on one core.
VerdictTimes verdict_stages(const fs::path& project, const std::string& preset) {
  namespace rs = rockface::storage;
  namespace rf = rockface::faces;
  namespace rk = rockface::kinematics;
  rs::OpenOptions open;
  open.read_only = true;
  rs::ProjectStore store = rs::ProjectStore::open(project, open);
  // The visit's analysis input from its rows, then the trace map's input as
  // the analysis makes it (core/analysis).
  const rockface::analysis::AnalysisInput input =
      rs::visit_analysis_input(rs::load_scene_source(store), project.string());
  const rockface::analysis::TraceMapInput map = rockface::analysis::trace_map_input(input);

  // The fastest of kRepeats runs of each stage: the machine is shared, and
  // the least disturbed run is the closest to the stage's own cost.
  constexpr int kRepeats = 10;
  VerdictTimes best;
  for (int rep = 0; rep < kRepeats; ++rep) {
    const VerdictTimes t =
        verdict_stages_once(map.patches, map.traces, input.density, map.snap_tolerance,
                            map.orientation_uncertainty, map.datum, preset);
    if (rep == 0) best = t;
    best.trace_map_ms = std::min(best.trace_map_ms, t.trace_map_ms);
    best.blocks_ms = std::min(best.blocks_ms, t.blocks_ms);
    best.rotation_ms = std::min(best.rotation_ms, t.rotation_ms);
    best.remote_ms = std::min(best.remote_ms, t.remote_ms);
    best.remote_all_ms = std::min(best.remote_all_ms, t.remote_all_ms);
  }
  return best;
}

void face_to_verdicts(benchmark::State& state, const std::string& preset) {
  const fs::path project = work_dir() / (preset + ".rockface");
  ReplayRun run;
  VerdictTimes v;
  for (auto _ : state) {
    fs::remove(project);
    run = run_replay(preset, project);
    if (!run.ok()) {
      state.SkipWithError("rockface replay failed (run it by hand on the scene)");
      return;
    }
    v = verdict_stages(project, preset);
  }
  std::map<std::string, double> end_s, hwm;
  double last = 0;
  std::string stage = "capture";
  for (const auto& m : run.marks) {
    const std::string s = stage_of(m.stage, stage);
    if (s != stage) {
      end_s[stage] = m.at_s;
      hwm[stage] = m.hwm_mb;
      stage = s;
    }
  }
  end_s[stage] = run.total_s;
  hwm[stage] = run.peak_mb;
  for (const char* s :
       {"capture", "features", "orientation", "dense", "registration", "analysis"}) {
    if (!end_s.count(s)) continue;
    state.counters[std::string(s) + "_s"] = end_s[s] - last;
    state.counters[std::string(s) + "_MB"] = hwm[s];
    last = end_s[s];
  }
  state.counters["total_s"] = run.total_s;
  state.counters["peak_MB"] = run.peak_mb;
  state.counters["trace_map_ms"] = v.trace_map_ms;
  state.counters["blocks_ms"] = v.blocks_ms;
  state.counters["rotation_ms"] = v.rotation_ms;
  state.counters["remote_ms"] = v.remote_ms;
  state.counters["blocks"] = v.blocks;
  state.counters["finite"] = v.finite;
  state.counters["searched"] = v.searched;
  state.counters["remote_starts"] = v.remote_starts;
  state.counters["remote_all_ms"] = v.remote_all_ms;
  state.counters["remote_all_starts"] = v.remote_all_starts;
}

}  // namespace

int main(int argc, char** argv) {
  for (const char* preset : {"fast", "standard", "precise"})
    benchmark::RegisterBenchmark(
        (std::string("face_to_verdicts/") + preset).c_str(),
        [preset](benchmark::State& state) { face_to_verdicts(state, preset); })
        ->Iterations(1)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  fs::remove_all(work_dir());  // the projects (the precise one holds a 4 M-point model)
  return 0;
}
