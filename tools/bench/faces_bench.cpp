// Trace map: time from N joint traces on a five-patch benched slope to all
// blocks with their verdicts (surface model, trace planes, snapping and
// splitting, loops by Lu's rule, block construction and the single-block
// analysis of every loop). The slope is 40 m long; traces are drawn from
// three joint sets at random places with random lengths (fixed seed), and
// each is marked with a few millimetres of hand error.
#include <cmath>
#include <memory>

#include <benchmark/benchmark.h>

#include "core/common/progress.h"
#include "core/common/units.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/faces/trace_session.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/kinematics/quick_checks.h"
#include "core/kinematics/remote_axis.h"
#include "core/kinematics/rotation_input.h"
#include "tests/support/random_slope.h"

namespace {

using namespace rockface;
using V = Eigen::Vector3d;

using faces::testing::kSnap;
using faces::testing::random_traces;

// The options of every run here: the scene default tolerance, 1 degree,
// gravity (effects: the caller's, to outlive the options).
faces::TraceBlockOptions map_options(kinematics::Effects& effects) {
  effects.push_back(std::make_unique<kinematics::GravityEffect>(V(0, 0, -9.81)));
  faces::TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  options.orientation_uncertainty = deg_to_rad(1.0);
  options.effects = &effects;
  return options;
}

void BM_TraceMapToBlocks(benchmark::State& state) {
  const auto patches = faces::testing::random_slope();
  const faces::FreeSurface probe = faces::FreeSurface::build(patches, kSnap);
  const auto traces = random_traces(probe, static_cast<int>(state.range(0)), 11);
  kinematics::Effects effects;
  const faces::TraceBlockOptions options = map_options(effects);
  NoProgress progress;
  size_t loops = 0, finite = 0, removable = 0, vertices = 0, islands = 0, unassembled = 0;
  for (auto _ : state) {
    const auto surface = faces::FreeSurface::build(patches, kSnap);
    const auto net = faces::TraceNetwork::build(surface, traces, {kSnap, deg_to_rad(1.0)});
    const auto found = faces::SurfaceLoops::find(net, surface);
    const auto blocks = faces::trace_blocks(surface, net, found, options, progress);
    benchmark::DoNotOptimize(blocks.data());
    loops = found.regions().size();
    vertices = net.vertices().size();
    finite = removable = islands = unassembled = 0;
    for (const auto& r : found.regions()) islands += r.loops.size() > 1 ? 1 : 0;
    for (const auto& b : blocks) {
      finite += b.finite ? 1 : 0;
      removable += b.finiteness.removable.value ? 1 : 0;
      for (const auto& n : b.notes) unassembled += n.find("not assembled") != std::string::npos;
    }
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["loops"] = static_cast<double>(loops);
  state.counters["finite"] = static_cast<double>(finite);
  state.counters["removable"] = static_cast<double>(removable);
  state.counters["with_islands"] = static_cast<double>(islands);
  state.counters["not_assembled"] = static_cast<double>(unassembled);
}
BENCHMARK(BM_TraceMapToBlocks)->Arg(50)->Arg(200)->Arg(1000)->Unit(benchmark::kMillisecond);

// Issue 26: TraceNetwork::build alone (planes and stretches, laying on
// patch edges, merging, crossings and extensions, vertices, edges, the order
// around each vertex) on the surface built once, to time its phases apart
// from the loop search and the block analysis that dilute them above.
void BM_TraceNetworkBuild(benchmark::State& state) {
  const auto patches = faces::testing::random_slope();
  const faces::FreeSurface surface = faces::FreeSurface::build(patches, kSnap);
  const auto traces = random_traces(surface, static_cast<int>(state.range(0)), 11);
  size_t vertices = 0, edges = 0;
  for (auto _ : state) {
    const auto net = faces::TraceNetwork::build(surface, traces, {kSnap, deg_to_rad(1.0)});
    benchmark::DoNotOptimize(net.vertices().data());
    vertices = net.vertices().size();
    edges = net.edges().size();
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["edges"] = static_cast<double>(edges);
}
BENCHMARK(BM_TraceNetworkBuild)->Arg(200)->Arg(1000)->Unit(benchmark::kMillisecond);

// The finite blocks of the map of `count` traces that are one polyhedron
// each (the map built once, for the benchmarks that time what follows).
std::vector<blocks::Polyhedron> finite_polyhedra(int count) {
  const auto patches = faces::testing::random_slope();
  const faces::FreeSurface surface = faces::FreeSurface::build(patches, kSnap);
  const auto traces = random_traces(surface, count, 11);
  faces::TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  options.orientation_uncertainty = deg_to_rad(1.0);
  NoProgress progress;
  const auto net = faces::TraceNetwork::build(surface, traces, {kSnap, deg_to_rad(1.0)});
  const auto found = faces::SurfaceLoops::find(net, surface);
  std::vector<blocks::Polyhedron> out;
  for (const auto& b : faces::trace_blocks(surface, net, found, options, progress))
    if (b.finite && b.polyhedron) out.push_back(*b.polyhedron);
  return out;
}

// Issue 17: the quick checks (finiteness, removability, corner / edge
// rotatability) of every finite block of the map that is one polyhedron,
// after the map is built (outside the timed loop), on range(1) threads;
// wall time.
void BM_TraceMapQuickChecks(benchmark::State& state) {
  const std::vector<blocks::Polyhedron> polyhedra =
      finite_polyhedra(static_cast<int>(state.range(0)));
  size_t corners = 0;
  for (auto _ : state) {
    const auto q = kinematics::quick_checks_all(polyhedra, deg_to_rad(1.0),
                                                static_cast<unsigned>(state.range(1)));
    corners = 0;
    for (const auto& x : q) corners += x.rotation.corners.size();
    benchmark::DoNotOptimize(q.data());
  }
  state.counters["blocks"] = static_cast<double>(polyhedra.size());
  state.counters["static_points"] = static_cast<double>(corners);
}
// Issue 17: the remote-axis search over every finite block of the map at the
// standard preset's 64 starts, one thread (the map is built outside the
// timed loop; rotation is timed too, as the report needs it to decide).
// range(1) = 0: every block searched with all its starts (as before issue
// 17); 1: as the report does it - a block that rotates firmly about a
// corner or an edge is not searched (kinematics::firm_corner_or_edge_axis),
// the others stop early once the hit rate has settled.
void BM_TraceMapRemoteAxis(benchmark::State& state) {
  std::vector<kinematics::RotationInput> inputs;
  for (const auto& p : finite_polyhedra(static_cast<int>(state.range(0))))
    inputs.push_back(kinematics::rotation_input(p));
  const bool as_reported = state.range(1) != 0;
  long searched = 0, starts = 0, with_axis = 0;
  for (auto _ : state) {
    searched = starts = with_axis = 0;
    for (const auto& in : inputs) {
      if (as_reported) {
        const auto rotation = kinematics::analyse_rotation(in, deg_to_rad(1.0));
        if (kinematics::firm_corner_or_edge_axis(rotation)) {
          ++with_axis;
          continue;
        }
      }
      const auto r = kinematics::search_remote_axis(in, {64, 1, as_reported});
      ++searched;
      starts += r.starts;
      with_axis += r.found ? 1 : 0;
    }
  }
  state.counters["blocks"] = static_cast<double>(inputs.size());
  state.counters["searched"] = static_cast<double>(searched);
  state.counters["starts_run"] = static_cast<double>(starts);
  state.counters["with_axis"] = static_cast<double>(with_axis);
}
BENCHMARK(BM_TraceMapRemoteAxis)
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// Issue 17: from one edited trace to updated verdicts (faces::TraceSession):
// a trace of a finite block moved 0.2 m sideways and back, alternately, on
// the map of range(0) traces; each update rebuilds the network and loops and
// recomputes the regions that changed (wall time per update).
void BM_TraceEditToVerdicts(benchmark::State& state) {
  const auto patches = faces::testing::random_slope();
  const faces::FreeSurface surface = faces::FreeSurface::build(patches, kSnap);
  auto traces = random_traces(surface, static_cast<int>(state.range(0)), 11);
  kinematics::Effects effects;
  const faces::TraceBlockOptions options = map_options(effects);
  NoProgress progress;
  faces::TraceSession session(patches, {kSnap, deg_to_rad(1.0)}, options);
  session.update(traces, progress);
  const int regions = session.recomputed();
  int k = -1;
  for (const auto& b : session.blocks())
    if (b.finite) k = b.traces.front();
  if (k < 0) {
    state.SkipWithError("no finite block");
    return;
  }
  const V p0 = traces[k].points.front();
  V side = V::UnitX();
  for (const auto& P : surface.patches())
    if (std::abs(P.height(p0)) < 0.01 && P.contains(P.to2d(p0), 0.01))
      side = P.outward.cross(traces[k].points.back() - p0).normalized();
  const auto original = traces[k].points;
  long recomputed = 0, updates = 0;
  for (auto _ : state) {
    const bool out = updates % 2 == 0;
    for (size_t i = 0; i < original.size(); ++i)
      traces[k].points[i] = original[i] + (out ? 0.2 : 0.0) * side;
    benchmark::DoNotOptimize(session.update(traces, progress).data());
    recomputed += session.recomputed();
    ++updates;
  }
  state.counters["regions"] = regions;
  state.counters["recomputed"] = static_cast<double>(recomputed) / static_cast<double>(updates);
}
BENCHMARK(BM_TraceEditToVerdicts)
    ->Arg(200)
    ->Arg(1000)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK(BM_TraceMapQuickChecks)
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
