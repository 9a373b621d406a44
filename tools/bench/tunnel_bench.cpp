// The tunnel drive: what its answers cost in time (docs/accuracy-cost.md,
// "The tunnel drive").
//
// - profile deviation against mesh size: a 10 m tube (circle of 3 m design
//   radius, surface at 3.25 m) tessellated ever finer, 41 sections every
//   0.25 m, rays every 5 cm of outline (377 a section); the BVH's build is
//   included (it is built per call). Counter: the relative error of the
//   overbreak volume against pi (R^2 - r^2) L.
// - profile deviation against ray and section spacing: a pocket of 0.2 m
//   overbreak whose edges fall anywhere between rays and sections (60.5 deg
//   of the outline, chainage 3.03 to 5.07 m), on a fine mesh; counter: the
//   error of the pocket's volume against its closed form.
// - the sets along the drive: 1,000 (and 10,000) synthetic visits of three
//   sets scattering within their cones, one of which turns at every 100th
//   visit.
// - place(): points around a curved, graded alignment.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <benchmark/benchmark.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/drive_sets.h"
#include "core/tunnel/mesh_raycast.h"
#include "core/tunnel/profile_deviation.h"

namespace rt = rockface::tunnel;

namespace {

constexpr double kPi = std::numbers::pi;

rt::Alignment north_tunnel() {
  const Eigen::Vector3d datum(2690000, 1250000, 500);
  return rt::Alignment::from_elements({{0, datum}, {20, datum + Eigen::Vector3d(0, 20, 0.2)}}, {0},
                                      datum);
}

struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// A tube from chainage 0 to 10 with `columns` facets round and rows at
// `chainages`, radius radius(theta, c) at each quad's middle.
template <class Radius>
Mesh tube(const rt::Alignment& al, int columns, const std::vector<double>& chainages,
          Radius radius) {
  Mesh m;
  for (std::size_t j = 0; j + 1 < chainages.size(); ++j)
    for (int i = 0; i < columns; ++i) {
      const double t0 = 2 * kPi * i / columns, t1 = 2 * kPi * (i + 1) / columns;
      const double r = radius((t0 + t1) / 2, (chainages[j] + chainages[j + 1]) / 2);
      const int base = static_cast<int>(m.vertices.size());
      for (double c : {chainages[j], chainages[j + 1]}) {
        const rt::TunnelFrame f = al.frame_at(c);
        for (double t : {t0, t1})
          m.vertices.push_back(f.to_local(r * std::cos(t), r * std::sin(t)));
      }
      m.triangles.push_back({base, base + 1, base + 3});
      m.triangles.push_back({base, base + 3, base + 2});
    }
  return m;
}

std::vector<double> rows(double step, std::vector<double> extra = {}) {
  std::vector<double> c;
  for (int k = 0; k * step <= 10 + 1e-9; ++k) c.push_back(k * step);
  c.insert(c.end(), extra.begin(), extra.end());
  std::sort(c.begin(), c.end());
  return c;
}

void BM_ProfileDeviationMeshSize(benchmark::State& state) {
  // columns x rows x 2 triangles: 360 x 14 = 10 k, 720 x 70 = 100 k, 1440 x 350 = 1 M.
  const int columns = static_cast<int>(state.range(0));
  const double step = 10.0 / static_cast<double>(state.range(1));
  const rt::Alignment al = north_tunnel();
  const Mesh m = tube(al, columns, rows(step), [](double, double) { return 3.25; });
  const rt::DesignProfile design = rt::circle_profile(3.0);
  rt::DeviationOptions o;
  o.chainage_from = 0.5;
  o.chainage_to = 9.5;
  o.section_spacing_m = 0.25;
  o.ray_spacing_m = 0.05;
  rt::ProfileDeviation d;
  for (auto _ : state) {
    d = rt::profile_deviation({m.vertices, m.triangles, {}, {}}, al, design, o);
    benchmark::DoNotOptimize(
        d.sections.data());  // not the double: old DoNotOptimize(double&) clobbers it on GCC
  }
  const double truth = kPi * (3.25 * 3.25 - 9) * 9.0;
  state.counters["triangles"] = static_cast<double>(m.triangles.size());
  state.counters["rays"] = static_cast<double>(d.rays_cast);
  state.counters["vol_err_pct"] = 100 * (d.overbreak_volume_m3 - truth) / truth;
}
BENCHMARK(BM_ProfileDeviationMeshSize)
    ->Args({360, 14})
    ->Args({720, 70})
    ->Args({1440, 350})
    ->Unit(benchmark::kMillisecond);

// The BVH alone, on the same meshes: how much of the above is its build.
void BM_RaycasterBuild(benchmark::State& state) {
  const int columns = static_cast<int>(state.range(0));
  const double step = 10.0 / static_cast<double>(state.range(1));
  const Mesh m = tube(north_tunnel(), columns, rows(step), [](double, double) { return 3.25; });
  for (auto _ : state) {
    const rt::MeshRaycaster caster(m.vertices, m.triangles);
    benchmark::DoNotOptimize(&caster);
  }
  state.counters["triangles"] = static_cast<double>(m.triangles.size());
}
BENCHMARK(BM_RaycasterBuild)
    ->Args({360, 14})
    ->Args({720, 70})
    ->Args({1440, 350})
    ->Unit(benchmark::kMillisecond);

void BM_ProfileDeviationSpacing(benchmark::State& state) {
  const double ray_spacing = static_cast<double>(state.range(0)) / 1000;
  const double section_spacing = static_cast<double>(state.range(1)) / 1000;
  const rt::Alignment al = north_tunnel();
  // The pocket's edges on the mesh's lines (exact step in the surface):
  // columns every 0.5 deg, rows every 0.05 m plus the pocket's ends.
  const double t0 = 17.0 * kPi / 180, t1 = 77.5 * kPi / 180, c0 = 3.03, c1 = 5.07;
  static const Mesh m = tube(al, 720, rows(0.05, {c0, c1}), [&](double t, double c) {
    return t > t0 && t < t1 && c > c0 && c < c1 ? 3.2 : 3.0;
  });
  rt::DeviationOptions o;
  o.chainage_from = 1;
  o.chainage_to = 8;
  o.section_spacing_m = section_spacing;
  o.ray_spacing_m = ray_spacing;
  rt::ProfileDeviation d;
  for (auto _ : state) {
    d = rt::profile_deviation({m.vertices, m.triangles, {}, {}}, al, rt::circle_profile(3.0), o);
    benchmark::DoNotOptimize(
        d.sections.data());  // not the double: old DoNotOptimize(double&) clobbers it on GCC
  }
  const double truth = 0.5 * (3.2 * 3.2 - 9) * (t1 - t0) * (c1 - c0);
  state.counters["rays"] = static_cast<double>(d.rays_cast);
  state.counters["vol_m3"] = d.overbreak_volume_m3;
  state.counters["vol_err_pct"] = 100 * (d.overbreak_volume_m3 - truth) / truth;
}
BENCHMARK(BM_ProfileDeviationSpacing)
    ->Args({200, 500})
    ->Args({100, 250})
    ->Args({50, 100})
    ->Args({20, 50})
    ->Args({10, 20})
    ->Unit(benchmark::kMillisecond);

std::vector<rt::VisitSets> synthetic_visits(int n) {
  std::mt19937 rng(7);
  std::normal_distribution<double> jitter(0, 0.4);
  std::vector<rt::VisitSets> v;
  for (int i = 0; i < n; ++i) {
    rt::VisitSets visit;
    visit.visit_id = i + 1;
    visit.chainage = 3.0 * i;
    // Set b's dip steps by 10 deg every 100 visits (a fold), back and forth.
    const double b_dip = 40 + 10 * ((i / 100) % 2);
    visit.sets = {
        {"a", rockface::geometry::plane_normal_deg(70 + jitter(rng), 120 + jitter(rng)), 80, 25},
        {"b", rockface::geometry::plane_normal_deg(b_dip + jitter(rng), 300 + jitter(rng)), 100,
         30},
        {"c", rockface::geometry::plane_normal_deg(20 + jitter(rng), 30 + jitter(rng)), 60, 15}};
    v.push_back(visit);
  }
  return v;
}

void BM_DriveSets(benchmark::State& state) {
  const auto visits = synthetic_visits(static_cast<int>(state.range(0)));
  rt::DriveSets d;
  for (auto _ : state) {
    d = rt::track_sets_along_drive(visits);
    benchmark::DoNotOptimize(d.tracks.data());
  }
  std::size_t turns = 0;
  for (const auto& t : d.tracks)
    for (const auto& e : t.events) turns += e.kind == rt::TrackEvent::Kind::turns;
  state.counters["tracks"] = static_cast<double>(d.tracks.size());
  state.counters["turns"] = static_cast<double>(turns);
}
BENCHMARK(BM_DriveSets)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_Place(benchmark::State& state) {
  // 50 elements: straights and arcs of radius 300 m alternating, 1 % grade.
  std::vector<rt::AlignmentStation> st;
  std::vector<double> radii;
  Eigen::Vector2d p(0, 0), dir(0, 1);
  double c = 0;
  st.push_back({0, {0, 0, 0}});
  for (int e = 0; e < 50; ++e) {
    const double len = 100;
    if (e % 2 == 0) {
      p += len * dir;
      radii.push_back(0);
    } else {
      const double R = 300, sweep = len / R;
      const Eigen::Vector2d right(dir.y(), -dir.x());
      const Eigen::Vector2d centre = p + R * right;
      const Eigen::Rotation2Dd turn(-sweep);
      p = centre + turn * (p - centre);
      dir = turn * dir;
      radii.push_back(R);
    }
    c += len;
    st.push_back({c, {p.x(), p.y(), 0.01 * c}});
  }
  const rt::Alignment al = rt::Alignment::from_elements(st, radii, Eigen::Vector3d::Zero());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ch(0, c), off(-6, 6);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 10000; ++i) pts.push_back(al.frame_at(ch(rng)).to_local(off(rng), off(rng)));
  for (auto _ : state)
    for (const auto& q : pts) {
      const rt::AlignmentPlace p = al.place(q);
      benchmark::DoNotOptimize(&p);
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 10000);
}
BENCHMARK(BM_Place)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
