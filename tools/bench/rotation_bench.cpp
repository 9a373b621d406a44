// Rotational kinematics: accuracy against time.
//  - Corner/edge rotatability per block against its number of faces (random
//    convex blocks cut from planes tangent to a sphere, one or two of them
//    free faces): the cost is the exact cone margin per static point,
//    O(m^4) in the m limit planes.
//  - Remote-axis search against the number of starts (8 .. 512): time per
//    search, mean hit rate, and the probability that the search finds the
//    axis at all (over 20 seeds) on the lined block of the tests, once with
//    a short lining, once just below the critical lining length and once
//    with a long lining (no axis exists).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/kinematics/remote_axis.h"
#include "core/kinematics/rotation_space.h"
#include "tests/support/rotation_blocks.h"

namespace {

using Eigen::Vector3d;
using rockface::kinematics::RotationInput;

// Random convex blocks with exactly `faces` faces (rejection sampling).
std::vector<RotationInput> random_blocks(int faces, int count) {
  std::mt19937 gen(1000 + faces);
  auto uniform = [&] { return (static_cast<double>(gen()) + 0.5) / 4294967296.0; };
  std::vector<RotationInput> blocks;
  for (int trial = 0; trial < 200 * count && static_cast<int>(blocks.size()) < count; ++trial) {
    std::vector<rockface::test_rotation::Side> sides;
    for (int i = 0; i < faces; ++i) {
      const double z = 2 * uniform() - 1, phi = 2 * M_PI * uniform();
      const Vector3d n(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi),
                       z);
      const double reach = 0.8 + 0.4 * uniform();
      sides.push_back({"P" + std::to_string(i), i >= 1 + trial % 2, -n, reach * n});
    }
    try {
      RotationInput in = rockface::test_rotation::convex_block("bench", sides);
      if (static_cast<int>(in.faces.size()) == faces) blocks.push_back(std::move(in));
    } catch (const std::exception&) {
    }
  }
  return blocks;
}

void BM_CornerEdgeRotation(benchmark::State& state) {
  const int faces = static_cast<int>(state.range(0));
  const auto blocks = random_blocks(faces, 16);
  if (blocks.empty()) {
    state.SkipWithError("no blocks");
    return;
  }
  size_t i = 0, corners = 0, limits = 0, runs = 0;
  for (auto _ : state) {
    const auto a =
        rockface::kinematics::analyse_rotation(blocks[i % blocks.size()], 1 * M_PI / 180);
    benchmark::DoNotOptimize(a);
    corners += a.corners.size();
    for (const auto& c : a.corners) limits += c.limits.size();
    ++i;
    ++runs;
  }
  state.counters["static_points"] = static_cast<double>(corners) / runs;
  state.counters["limit_planes"] = corners ? static_cast<double>(limits) / corners : 0;
  state.counters["vertices"] = static_cast<double>(blocks[0].vertices.size());
}
BENCHMARK(BM_CornerEdgeRotation)
    ->Arg(4)
    ->Arg(5)
    ->Arg(6)
    ->Arg(8)
    ->Arg(10)
    ->Arg(12)
    ->Arg(16)
    ->Arg(20)
    ->Unit(benchmark::kMillisecond);

RotationInput lined_block(double lining) {
  const double b = 30 * M_PI / 180, k = 70 * M_PI / 180, f = 80 * M_PI / 180;
  return rockface::test_rotation::convex_block(
      "lined", {{"L", true, {1, 0, 0}, {0, 0, 0}},
                {"F", false, {std::sin(f), 0, -std::cos(f)}, {0, 0, lining}},
                {"B", true, {-std::sin(b), 0, std::cos(b)}, {0, 0, 0}},
                {"K", true, {-std::sin(k), 0, -std::cos(k)}, {2, 0, 0}},
                {"S1", true, {0, 1, 0}, {0, -1, 0}},
                {"S2", true, {0, -1, 0}, {0, 1, 0}}});
}

// range(0): starts; range(1): lining length in mm (150: short; 280: just
// below the critical 291.5 mm; 600: long, no feasible axis - the cost of a
// search that finds nothing).
void BM_RemoteAxis(benchmark::State& state) {
  const int starts = static_cast<int>(state.range(0));
  const RotationInput in = lined_block(state.range(1) / 1000.0);
  // Accuracy over 20 seeds, outside the timed loop.
  constexpr int kSeeds = 20;
  long hits = 0, found = 0;
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    const auto r = rockface::kinematics::search_remote_axis(in, {starts, seed});
    hits += r.hits;
    found += r.found;
  }
  for (auto _ : state) {
    const auto r = rockface::kinematics::search_remote_axis(in, {starts, 1});
    benchmark::DoNotOptimize(r);
  }
  state.counters["hit_rate"] = static_cast<double>(hits) / (static_cast<double>(kSeeds) * starts);
  state.counters["found"] = static_cast<double>(found) / kSeeds;
}
BENCHMARK(BM_RemoteAxis)
    ->ArgsProduct({{8, 16, 32, 64, 128, 256, 512}, {150, 280, 600}})
    ->Unit(benchmark::kMillisecond);

// The same with the early stop (issue 17): starts actually run, and how
// often the verdict is the full search's (over 20 seeds).
void BM_RemoteAxisEarlyStop(benchmark::State& state) {
  const int starts = static_cast<int>(state.range(0));
  const RotationInput in = lined_block(state.range(1) / 1000.0);
  constexpr int kSeeds = 20;
  long run = 0, agree = 0;
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    const auto early = rockface::kinematics::search_remote_axis(in, {starts, seed, true});
    const auto full = rockface::kinematics::search_remote_axis(in, {starts, seed});
    run += early.starts;
    agree += early.found == full.found;
  }
  for (auto _ : state) {
    const auto r = rockface::kinematics::search_remote_axis(in, {starts, 1, true});
    benchmark::DoNotOptimize(r);
  }
  state.counters["starts_run"] = static_cast<double>(run) / kSeeds;
  state.counters["same_verdict"] = static_cast<double>(agree) / kSeeds;
}
BENCHMARK(BM_RemoteAxisEarlyStop)
    ->ArgsProduct({{16, 64, 256}, {150, 280, 600}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
