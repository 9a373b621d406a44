// Wedges around the excavation: what the search costs (docs/accuracy-cost.md,
// "Wedges around the excavation").
//
// - against the number of sets (3 to 8): every triple of sets and each of
//   its eight joint pyramids, on the sample's horseshoe (5 segments, arcs
//   drawn to the standard preset's 2 mm sagitta); counters: the triples and
//   the wedges found.
// - against the profile's segments: a regular polygon of 4 to 256 sides
//   (circumradius 3 m), three sets; counter: the wedges.
// - against the arcs' sagitta (the presets' knob): a circle of 3 m, three
//   symmetric sets; counter: the roof wedge's volume error against the same
//   wedge drawn to 1e-5 m.
// - with pattern bolts (1 m) and shotcrete on every wedge, three sets.
#include <cmath>
#include <numbers>

#include <benchmark/benchmark.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/wedge_analysis.h"

namespace rt = rockface::tunnel;

namespace {

constexpr double kRad = std::numbers::pi / 180;

// Eight sets spread over the stereonet as a face mapping gives them.
std::vector<rt::WedgeJointSet> sets(int n) {
  const double dips[] = {65, 60, 55, 30, 80, 45, 75, 20};
  const double dirs[] = {20, 145, 260, 330, 95, 200, 300, 60};
  std::vector<rt::WedgeJointSet> s;
  for (int i = 0; i < n; ++i)
    s.push_back({"J" + std::to_string(i + 1),
                 rockface::geometry::plane_normal_deg(dips[i], dirs[i]), 30 * kRad, 0});
  return s;
}

rt::TunnelFrame axis() {
  return rt::axis_frame(35 * kRad, 2 * kRad, Eigen::Vector3d::Zero(), "axis");
}

rt::DesignProfile polygon(int sides) {
  std::vector<rt::ProfileSegment> segs;
  for (int i = 0; i < sides; ++i) {
    const double a = -std::numbers::pi / 2 + 2 * std::numbers::pi * i / sides;
    const double b = a + 2 * std::numbers::pi / sides;
    segs.push_back(rt::ProfileSegment::line({3 * std::cos(a), 3 * std::sin(a)},
                                            {3 * std::cos(b), 3 * std::sin(b)}));
  }
  return rt::DesignProfile(segs);
}

void BM_WedgeSearchSets(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto profile = rt::horseshoe_profile(3, 1, 5, -1.5);
  const auto s = sets(n);
  std::size_t wedges = 0;
  for (auto _ : state) {
    const auto a = rt::analyse_wedges(profile, axis(), Eigen::Vector3d::Zero(), s, {});
    wedges = a.wedges.size();
    benchmark::DoNotOptimize(wedges);
  }
  state.counters["triples"] = n * (n - 1) * (n - 2) / 6;
  state.counters["wedges"] = static_cast<double>(wedges);
}
BENCHMARK(BM_WedgeSearchSets)->DenseRange(3, 8)->Unit(benchmark::kMillisecond);

void BM_WedgeSearchSegments(benchmark::State& state) {
  const auto profile = polygon(static_cast<int>(state.range(0)));
  const auto s = sets(3);
  std::size_t wedges = 0;
  for (auto _ : state) {
    const auto a = rt::analyse_wedges(profile, axis(), Eigen::Vector3d::Zero(), s, {});
    wedges = a.wedges.size();
    benchmark::DoNotOptimize(wedges);
  }
  state.counters["wedges"] = static_cast<double>(wedges);
}
BENCHMARK(BM_WedgeSearchSegments)->RangeMultiplier(4)->Range(4, 256)->Unit(benchmark::kMillisecond);

double roof_volume(const rt::WedgeAnalysis& a) {
  for (const auto& w : a.wedges)
    if (w.code == "111") return w.mass.volume;
  return NAN;
}

void BM_WedgeSagitta(benchmark::State& state) {
  const double sagitta = state.range(0) * 1e-4;  // m
  std::vector<rt::WedgeJointSet> s;
  for (int i = 0; i < 3; ++i)
    s.push_back({"J" + std::to_string(i + 1), rockface::geometry::plane_normal_deg(60, 120.0 * i),
                 30 * kRad, 0});
  const auto frame = rt::axis_frame(0, 0, Eigen::Vector3d::Zero(), "axis");
  rt::WedgeOptions fine;
  fine.sagitta_m = 1e-5;
  const double truth = roof_volume(
      rt::analyse_wedges(rt::circle_profile(3), frame, Eigen::Vector3d::Zero(), s, fine));
  rt::WedgeOptions o;
  o.sagitta_m = sagitta;
  double v = 0;
  for (auto _ : state) {
    v = roof_volume(
        rt::analyse_wedges(rt::circle_profile(3), frame, Eigen::Vector3d::Zero(), s, o));
    benchmark::DoNotOptimize(v);
  }
  state.counters["sagitta_mm"] = sagitta * 1000;
  state.counters["roof_vol_err_rel"] = std::abs(v - truth) / truth;
}
// 100 (fast), 20 (standard), 5 (precise) x 0.1 mm.
BENCHMARK(BM_WedgeSagitta)->Arg(100)->Arg(20)->Arg(5)->Unit(benchmark::kMillisecond);

void BM_WedgeSupport(benchmark::State& state) {
  const auto profile = rt::horseshoe_profile(3, 1, 5, -1.5);
  rt::WedgeOptions o;
  rt::PatternBolts b;
  b.length = 3;
  b.spacing = 1.0;
  b.capacity = 1e5;
  o.bolts = b;
  rt::Shotcrete c;
  c.thickness = 0.05;
  c.shear_strength = 1e6;
  o.shotcrete = c;
  const auto s = sets(3);
  int bolts = 0;
  for (auto _ : state) {
    const auto a = rt::analyse_wedges(profile, axis(), Eigen::Vector3d::Zero(), s, o);
    bolts = 0;
    for (const auto& w : a.wedges) bolts += static_cast<int>(w.bolts.size());
    benchmark::DoNotOptimize(bolts);
  }
  state.counters["bolts"] = bolts;
}
BENCHMARK(BM_WedgeSupport)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
