// The rock mass in figures: what a visit's figures cost in time
// (docs/accuracy-cost.md, "The rock mass in figures").
//
// A face 12 x 6 m cut by three sets (60/200, 75/110, 20/350) whose spacings
// are scaled down to give more and more traces (about 30 to 1,000), each
// trace the exact line of its plane on the face, plus finite blocks to size
// (one per ten traces). The whole of core/rockmass runs: window, sets,
// spacing, persistence, scanline RQD in three directions, Jv, block sizes,
// RMR89 and Q. Counters: the traces, the largest relative error of a set's
// mean spacing against its design value (exact lines: the arithmetic only),
// the mean scanline RQD.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/geometry/orientation.h"
#include "core/rockmass/rock_mass_figures.h"

namespace rm = rockface::rockmass;

namespace {

constexpr double kW = 12, kH = 6;

void add_set(std::vector<rm::FaceTrace>& traces, const Eigen::Vector3d& n, double s, double d0,
             const std::string& set) {
  const Eigen::Vector2d along(n.z(), -n.x());
  const Eigen::Vector3d corners[4] = {{0, 0, 0}, {kW, 0, 0}, {kW, 0, kH}, {0, 0, kH}};
  double lo = 1e9, hi = -1e9;
  for (const auto& c : corners) {
    lo = std::min(lo, n.dot(c));
    hi = std::max(hi, n.dot(c));
  }
  const double q = n.x() * n.x() + n.z() * n.z();
  for (double d = d0 + std::ceil((lo - d0) / s) * s; d < hi; d += s) {
    const Eigen::Vector2d base = d * Eigen::Vector2d(n.x(), n.z()) / q;
    double t0 = -1e9, t1 = 1e9;
    const double bound[2] = {kW, kH};
    bool inside = true;
    for (int a = 0; a < 2; ++a) {
      if (std::abs(along[a]) < 1e-12) {
        inside = inside && base[a] >= 0 && base[a] <= bound[a];
        continue;
      }
      double u = -base[a] / along[a], v = (bound[a] - base[a]) / along[a];
      if (u > v) std::swap(u, v);
      t0 = std::max(t0, u);
      t1 = std::min(t1, v);
    }
    if (!inside || t1 - t0 < 1e-6) continue;
    rm::FaceTrace t;
    t.label = "T" + std::to_string(traces.size() + 1);
    t.set_label = set;
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const Eigen::Vector2d p = base + (t0 + f * (t1 - t0)) * along;
      t.points.push_back({p.x(), 0, p.y()});
    }
    t.length_m = t1 - t0;
    t.censored = t0 > -1e8;
    traces.push_back(std::move(t));
  }
}

const double kDesign[3] = {0.8, 1.0, 1.2};

rm::RockMassInput face(double scale) {
  rm::RockMassInput in;
  const double orient[3][2] = {{60, 200}, {75, 110}, {20, 350}};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d n = rockface::geometry::plane_normal_deg(orient[k][0], orient[k][1]);
    const std::string label = "S" + std::to_string(k + 1);
    in.sets.push_back({label, n});
    add_set(in.traces, n, kDesign[k] * scale, 0.013 * (k + 1), label);
  }
  for (std::size_t i = 0; i < in.traces.size() / 10; ++i)
    in.blocks.push_back({"B" + std::to_string(i), 0.01 * static_cast<double>(i + 1),
                         Eigen::Vector3d(10, 20, 25), 2700.0 * 0.01 * static_cast<double>(i + 1)});
  in.form.ucs_mpa = 120;
  in.form.jr = 1.5;
  in.form.ja = 1;
  in.form.jw = 1;
  in.form.srf = 1;
  return in;
}

void BM_RockMassFigures(benchmark::State& state) {
  const double scale = 1.0 / static_cast<double>(state.range(0));
  const rm::RockMassInput in = face(scale);
  rm::RockMassFigures f;
  for (auto _ : state) {
    f = rm::rock_mass_figures(in);
    benchmark::DoNotOptimize(f.q.q);
  }
  double worst = 0;
  for (int k = 0; k < 3; ++k)
    if (f.spacings[k].mean_m)
      worst = std::max(worst, std::abs(*f.spacings[k].mean_m / (kDesign[k] * scale) - 1));
  state.counters["traces"] = static_cast<double>(in.traces.size());
  state.counters["spacing_rel_err"] = worst;
  state.counters["rqd_pct"] = f.scanlines.rqd_percent.value_or(-1);
}
BENCHMARK(BM_RockMassFigures)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
