// Trace map: time from N joint traces on a five-patch benched slope to all
// blocks with their verdicts (surface model, trace planes, snapping and
// splitting, loops by Lu's rule, block construction and the single-block
// analysis of every loop). The slope is 40 m long; traces are drawn from
// three joint sets at random places with random lengths (fixed seed), and
// each is marked with a few millimetres of hand error.
#include <cmath>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>

#include "core/common/progress.h"
#include "core/common/units.h"
#include "core/faces/free_surface.h"
#include "core/faces/surface_loops.h"
#include "core/faces/trace_blocks.h"
#include "core/faces/trace_network.h"
#include "core/kinematics/effect_gravity.h"

namespace {

using namespace rockface;
using V = Eigen::Vector3d;

constexpr double kLength = 40;  // m along strike
constexpr double kSnap = 0.05;   // m, the scene default

std::vector<faces::PatchInput> slope() {
  return {
      {"floor", {V(-10, 0, 0), V(0, 0, 0), V(0, kLength, 0), V(-10, kLength, 0)}},
      {"lower face", {V(0, 0, 0), V(3, 0, 6), V(3, kLength, 6), V(0, kLength, 0)}},
      {"bench", {V(3, 0, 6), V(8, 0, 6), V(8, kLength, 6), V(3, kLength, 6)}},
      {"upper face", {V(8, 0, 6), V(11, 0, 12), V(11, kLength, 12), V(8, kLength, 6)}},
      {"top", {V(11, 0, 12), V(21, 0, 12), V(21, kLength, 12), V(11, kLength, 12)}},
  };
}

faces::TraceJoint joint_set(int k) {
  // Cross joints along the dip, a set dipping out of the faces, one into them.
  static const double dip[3] = {85, 35, 70}, dipdir[3] = {10, 265, 80};
  faces::TraceJoint j;
  j.index = k;
  j.id = "J" + std::to_string(k + 1);
  j.orientation = {deg_to_rad(dip[k]), deg_to_rad(dipdir[k])};
  j.friction = deg_to_rad(32);
  return j;
}

std::vector<faces::TraceInput> random_traces(const faces::FreeSurface& surface, int n,
                                             unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1), jitter(-0.003, 0.003);
  std::uniform_int_distribution<int> set(0, 2), patch(0, 4);
  std::vector<faces::TraceInput> traces;
  while (static_cast<int>(traces.size()) < n) {
    const faces::SurfacePatch& P = surface.patches()[patch(rng)];
    // A random point of the patch: bilinear in its (rectangular) corners.
    const V a = P.polygon[0], b = P.polygon[1], d = P.polygon[3];
    const V centre = a + unit(rng) * (b - a) + unit(rng) * (d - a);
    const faces::TraceJoint j = joint_set(set(rng));
    const V dir = geometry::plane_normal(j.orientation).cross(P.outward);
    if (dir.norm() < 0.1) continue;
    const double half = 1 + 3 * unit(rng);
    faces::TraceInput t;
    t.id = "T" + std::to_string(traces.size() + 1);
    t.joint = j;
    for (double s : {-half, 0.0, half}) {
      V p = centre + s * dir.normalized() + jitter(rng) * P.e1 + jitter(rng) * P.e2;
      const Eigen::Vector2d q = P.to2d(p);
      if (!P.contains(q, 0)) continue;  // keep the marking on its patch
      t.points.push_back(p);
    }
    if (t.points.size() >= 2) traces.push_back(std::move(t));
  }
  return traces;
}

void BM_TraceMapToBlocks(benchmark::State& state) {
  const auto patches = slope();
  const faces::FreeSurface probe = faces::FreeSurface::build(patches, kSnap);
  const auto traces = random_traces(probe, static_cast<int>(state.range(0)), 11);
  kinematics::Effects effects;
  effects.push_back(std::make_unique<kinematics::GravityEffect>(V(0, 0, -9.81)));
  faces::TraceBlockOptions options;
  options.snap_tolerance = kSnap;
  options.orientation_uncertainty = deg_to_rad(1.0);
  options.effects = &effects;
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

}  // namespace

BENCHMARK_MAIN();
