// Quick checks at field speed (issue 17): finiteness, removability and
// corner / edge rotatability of random convex blocks of 4 to 12 faces (the
// blocks of tests/core/kinematics/rotation/quick_checks_test.cpp), blocks per second on
// one core, per number of faces and for the mix of all sizes; and the mix
// on all cores (kinematics::quick_checks_all). The verdicts and margins
// are the test's: the same blocks, the same code.
//
//   quick_checks_bench --dump=FILE   writes the verdicts and margins of the
//                                    mix (the test's reference format) first
//   quick_checks_bench --once=FACES  runs the quick checks once on each of
//                                    the 20 blocks of FACES faces (0: the
//                                    mix of 180) and exits: a fixed workload
//                                    for callgrind's instruction counts
//                                    (--toggle-collect on quick_checks)
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "core/common/units.h"
#include "core/kinematics/quick_checks.h"
#include "tests/support/quick_check_blocks.h"

namespace {

using rockface::deg_to_rad;
namespace tr = rockface::test_rotation;

void run(benchmark::State& state, const std::vector<rockface::blocks::Polyhedron>& blocks) {
  if (blocks.empty()) {
    state.SkipWithError("no blocks");
    return;
  }
  size_t i = 0, corners = 0, runs = 0;
  for (auto _ : state) {
    const auto q = rockface::kinematics::quick_checks(blocks[i % blocks.size()], deg_to_rad(1.0));
    benchmark::DoNotOptimize(q);
    corners += q.rotation.corners.size();
    ++i;
    ++runs;
  }
  state.counters["blocks_per_s"] =
      benchmark::Counter(static_cast<double>(runs), benchmark::Counter::kIsRate);
  state.counters["static_points"] = static_cast<double>(corners) / static_cast<double>(runs);
}

void BM_QuickChecks(benchmark::State& state) {
  run(state, tr::quick_check_blocks(static_cast<int>(state.range(0)), 20));
}
BENCHMARK(BM_QuickChecks)->DenseRange(4, 12, 1)->Unit(benchmark::kMicrosecond);

// The test's mix: 20 blocks of each size 4..12.
void BM_QuickChecksMix(benchmark::State& state) {
  run(state, tr::quick_check_mix(20));
}
BENCHMARK(BM_QuickChecksMix)->Unit(benchmark::kMicrosecond);

// The mix on range(0) threads (kinematics::quick_checks_all), wall time:
// blocks per second of the machine, not of one core.
void BM_QuickChecksMixThreads(benchmark::State& state) {
  const auto blocks = tr::quick_check_mix(20);
  size_t done = 0;
  for (auto _ : state) {
    const auto q = rockface::kinematics::quick_checks_all(blocks, deg_to_rad(1.0),
                                                          static_cast<unsigned>(state.range(0)));
    benchmark::DoNotOptimize(q.data());
    done += blocks.size();
  }
  state.counters["blocks_per_s"] =
      benchmark::Counter(static_cast<double>(done), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_QuickChecksMixThreads)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  for (int k = 1; k < argc; ++k)
    if (std::strncmp(argv[k], "--dump=", 7) == 0) {
      std::ofstream out(argv[k] + 7);
      for (const auto& block : tr::quick_check_mix(20)) {
        const auto q = rockface::kinematics::quick_checks(block, deg_to_rad(1.0));
        out << tr::quick_checks_dump(block, q.finiteness, q.rotation);
      }
    }
  for (int k = 1; k < argc; ++k)
    if (std::strncmp(argv[k], "--once=", 7) == 0) {
      const int faces = std::atoi(argv[k] + 7);
      const auto blocks = faces > 0 ? tr::quick_check_blocks(faces, 20) : tr::quick_check_mix(20);
      size_t corners = 0;
      for (const auto& block : blocks)
        corners +=
            rockface::kinematics::quick_checks(block, deg_to_rad(1.0)).rotation.corners.size();
      std::printf("%zu blocks, %zu static points\n", blocks.size(), corners);
      return 0;
    }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
