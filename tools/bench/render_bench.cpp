// Synthetic render of a stereo pair (the mock camera's `rockface render`):
// time and peak memory against image size, up to a 24 Mpx pair (6000 x 4000,
// the tunnel-face sample's camera). The scene is the sample's geometry in
// datum-relative coordinates, with every imaging effect on.
//
//   build/<dir>/bench/render_bench --benchmark_counters_tabular=true
#include <sys/resource.h>

#include <benchmark/benchmark.h>

#include "camera/synthetic_renderer.h"
#include "core/common/progress.h"
#include "core/geometry/orientation.h"

namespace {

using Eigen::Vector3d;
using rockface::camera::SyntheticScene;

Vector3d normal(double dip, double dipdir) {
  constexpr double d = 3.14159265358979323846 / 180;
  return rockface::geometry::plane_normal({dip * d, dipdir * d});
}

SyntheticScene tunnel_face(int width) {
  SyntheticScene s;
  s.patches = {{"FACE_W", {{-3, 10, 0}, {0, 10.3, 0}, {0, 10.5, 5}, {-3, 10.2, 5}}},
               {"FACE_E", {{0, 10.3, 0}, {3, 10.1, 0}, {3, 10.3, 5}, {0, 10.5, 5}}},
               {"FLOOR", {{-3, 0, 0}, {3, 0, 0}, {3, 10.1, 0}, {0, 10.3, 0}, {-3, 10, 0}}},
               {"WALL_W", {{-3, 0, 0}, {-3, 10, 0}, {-3, 10.2, 5}, {-3, 0, 5}}},
               {"WALL_E", {{3, 0, 0}, {3, 0, 5}, {3, 10.3, 5}, {3, 10.1, 0}}}};
  s.joints = {{"J1", normal(60, 200), {-0.5, 10.35, 2.5}},
              {"J2", normal(75, 110), {1.0, 10.4, 3.0}},
              {"J3", normal(20, 350), {0.0, 10.3, 1.5}}};
  const double scale = width / 6000.0;
  s.camera.width = width;
  s.camera.height = width * 2 / 3;
  s.camera.fx = s.camera.fy = 8930 * scale;
  s.camera.cx = (2999.5 + 0.5) * scale - 0.5;
  s.camera.cy = (1999.5 + 0.5) * scale - 0.5;
  s.camera.distortion = {-0.08, 0.06, 0.0002, -0.0001, 0.0};
  s.stations[0] = {{-0.9, 0.5, 1.6}, {0, 10.3, 2.3}};
  s.stations[1] = {{0.9, 0.5, 1.6}, {0, 10.3, 2.3}};
  s.range_pole = rockface::camera::SyntheticRangePole{{1.6, 8.0, 0.9}, 2.0, 0.25};
  s.effects.distortion = true;
  s.effects.noise_sigma = 1.5;
  s.effects.blur_px = 0.5;
  s.effects.exposure = 1.0;
  s.texture_seed = 7;
  return s;
}

// CPU seconds of the whole process, all threads (the render runs on every core).
double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kB on Linux
}

void BM_RenderPair(benchmark::State& state) {
  const SyntheticScene scene = tunnel_face(static_cast<int>(state.range(0)));
  rockface::NoProgress quiet;
  const double cpu0 = process_cpu_s();
  for (auto _ : state) {
    auto render = rockface::camera::render_scene(scene, quiet);
    benchmark::DoNotOptimize(render.images[0].data);
  }
  const double mpx = 2.0 * scene.camera.width * scene.camera.height / 1e6;
  state.counters["Mpx_pair"] = mpx;
  state.counters["Mpx_per_s"] =
      benchmark::Counter(mpx * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["cpu_s_all_threads"] = (process_cpu_s() - cpu0) / state.iterations();
  state.counters["peak_RSS_MB"] = peak_rss_mb();
}

// Ascending sizes: the process's peak memory after each is that of the largest so far.
BENCHMARK(BM_RenderPair)
    ->Arg(1500)
    ->Arg(3000)
    ->Arg(6000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
