// Joint-pyramid enumeration and mode analysis: time against the number of
// joints (2^n codes). Each cone margin is exact (O(m^4) in its m half-spaces),
// so the cost grows as 2^n n^4; this shows where that stops being "instant".
#include <random>

#include <benchmark/benchmark.h>

#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/joint_pyramids.h"

namespace {

using namespace rockface;

std::vector<kinematics::JointSpec> random_joints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> dip(5, 89), dipdir(0, 360);
  std::vector<kinematics::JointSpec> js;
  for (int i = 0; i < n; ++i) {
    // Drawn in this order (dip, then dip direction): the order of a function's
    // arguments is unspecified.
    const double dip_deg = dip(rng);
    const double dipdir_deg = dipdir(rng);
    js.push_back({geometry::plane_normal_deg(dip_deg, dipdir_deg), deg_to_rad(30)});
  }
  return js;
}

void BM_PyramidsAndModes(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto joints = random_joints(n, 42);
  // A cut 70/180 with flat ground above it: one excavation pyramid of two faces.
  const geometry::Cone ep = kinematics::excavation_pyramid(
      {{geometry::plane_normal_deg(70, 180), geometry::HalfSpace::Lower},
       {Eigen::Vector3d::UnitZ(), geometry::HalfSpace::Lower}});
  kinematics::PyramidOptions opt;
  opt.uncertainty = deg_to_rad(1);
  opt.resultant = Eigen::Vector3d(0, 0, -9.81);
  size_t removable = 0;
  for (auto _ : state) {
    const auto vs = kinematics::analyse_joint_pyramids(joints, ep, opt);
    removable = 0;
    for (const auto& v : vs) removable += v.removable.value;
    benchmark::DoNotOptimize(removable);
  }
  state.counters["codes"] = static_cast<double>(size_t{1} << n);
  state.counters["removable"] = static_cast<double>(removable);
  state.counters["us_per_code"] = benchmark::Counter(
      static_cast<double>(size_t{1} << n),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PyramidsAndModes)->DenseRange(3, 12)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
