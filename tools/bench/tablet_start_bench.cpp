// The tablet's own waits (issue 45: "cold start to the Project screen
// ≤ 1.5 s; opening a project of 50 visits ≤ 1 s"), on the software renderer
// (Mesa llvmpipe through surfaceless EGL) at the tablet's 1280 x 800:
// - start-up to the first frame of the Project screen (EGL, ImGui, the
//   settings, the chooser listing the projects folder), in-process: the
//   process's own loading (the dynamic linker, about 0.1 s for the binary's
//   libraries) is not in it (docs/accuracy-cost.md gives the whole process);
// - opening a project of 50 visits from the chooser (the tap on "Open", the
//   frames until the Project screen lists its visits), and until its latest
//   visit's 3D image is loaded and shown (the worker's part);
// - the same with 5 visits, so the cost that grows with the visits shows.
//
// The projects: visits of the office benchmarks' tablet project
// (bench_tablet_projects.h: a photograph, a 3D image of `kMeshSide`² vertices,
// 18 measured planes, an analysis and a placement each), made once in
// $TMPDIR/rockface-tablet-start-bench/.
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <string>

#include "tools/bench/bench_tablet_projects.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using Clock = std::chrono::steady_clock;

// A 3D image of 300 x 300 vertices (180 k triangles): a face model of the
// fast preset's size; every visit has one, the latest is shown on open.
constexpr int kMeshSide = 300;

fs::path folder() {
  static const fs::path dir = fs::temp_directory_path() / "rockface-tablet-start-bench";
  fs::create_directories(dir);
  return dir;
}

storage::Model grid_model(storage::RecordId capture, int side) {
  return bench::grid_model(capture, side, "fast");
}

fs::path project_of(int visits) {
  const std::string name = "tablet-" + std::to_string(visits) + "-visits";
  return bench::make_bench_project(folder(), name, visits, 1200, 800, kMeshSide, grid_model);
}

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

ui::UiOptions chooser_options() {
  ui::UiOptions options;
  options.projects_folder = folder();
  return options;
}

void BM_StartUpToProjectScreen(benchmark::State& state) {
  project_of(50);  // the chooser lists it, as on a tablet in use
  for (auto _ : state) {
    ui::HeadlessSession s(chooser_options(), ui::FieldServices{}, 1280, 800);
    s.frame();
    if (!s.state().targets.find("Open tablet-50-visits")) {
      state.SkipWithError("the Project screen's chooser does not list the bench project");
      return;
    }
  }
}
BENCHMARK(BM_StartUpToProjectScreen)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void open_project(benchmark::State& state, int visits) {
  const fs::path file = project_of(visits);
  const std::string label = "Open " + file.stem().string();
  double listed_ms = 0, shown_ms = 0;
  for (auto _ : state) {
    state.PauseTiming();
    ui::HeadlessSession s(chooser_options(), ui::FieldServices{}, 1280, 800);
    s.frame();
    state.ResumeTiming();
    const auto t0 = Clock::now();
    s.tap(label, "bench");
    if (!s.state().session || s.state().session->visits().size() != std::size_t(visits)) {
      state.SkipWithError(("the project did not open with its " + std::to_string(visits) +
                           " visits: " + s.state().statuses.line(0))
                              .c_str());
      return;
    }
    listed_ms += ms_since(t0);
    s.tap("Model", "bench");
    s.settle();
    shown_ms += ms_since(t0);
    if (!s.state().model_view.has_model()) {
      state.SkipWithError("the latest visit's 3D image was not shown");
      return;
    }
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["listed_ms"] = listed_ms / n;
  state.counters["model_shown_ms"] = shown_ms / n;
}

void BM_OpenProject(benchmark::State& state) {
  open_project(state, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_OpenProject)
    ->Arg(5)
    ->Arg(50)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
