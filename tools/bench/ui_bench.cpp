// Tablet UI on the software renderer (Mesa llvmpipe through surfaceless
// EGL, what a tablet without a working GPU driver and every CI run use):
// - frame time of the Model screen at 1280 x 800 on the model of a 24 Mpx
//   stereo pair, per display-triangle budget (the knob: the model view is
//   a decimated copy of the stored mesh; picking always uses the full mesh);
// - time from a tap on the model to the updated dip (pick on the full mesh
//   + plane fit with uncertainty, then the frame that shows it);
// - start-up: EGL + ImGui + opening the project + loading and preparing the
//   model (decoding the texture, decimating, building the picker's BVH).
//
// The project: tools/bench/ui_bench_project.h.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "tools/bench/ui_bench_project.h"
#include "ui/mapping/trace_marker.h"
#include "ui/platform/headless_session.h"

namespace {

using namespace rockface::ui;

std::unique_ptr<HeadlessSession> open(std::size_t max_triangles) {
  UiOptions options;
  options.project = ui_bench_project();
  options.max_display_triangles = max_triangles;
  auto s = std::make_unique<HeadlessSession>(options, FieldServices{}, 1280, 800);
  s->settle();
  return s;
}

void BM_ModelFrame(benchmark::State& state) {
  if (!have_ui_bench_project(state)) return;
  auto s = open(static_cast<std::size_t>(state.range(0)));
  s->tap("Model");
  for (auto _ : state) s->frame();
  state.counters["shown_triangles"] =
      static_cast<double>(s->state().model_view.display_mesh().triangle_count());
  state.counters["model_triangles"] =
      static_cast<double>(s->state().model_view.surface()->triangles.size());
}
BENCHMARK(BM_ModelFrame)
    ->Arg(50000)
    ->Arg(200000)
    ->Arg(400000)
    ->Arg(1600000)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

// The same while a finger turns the model: each frame one move of a drag
// across the panel (the view draws the display mesh's turning copy, an
// eighth of the budget; issue 45 asks >= 30 frames a second).
void BM_ModelTurning(benchmark::State& state) {
  if (!have_ui_bench_project(state)) return;
  auto s = open(static_cast<std::size_t>(state.range(0)));
  s->tap("Model");
  const ModelView& view = s->state().model_view;
  const float cx = (view.panel_min().x + view.panel_max().x) / 2,
              cy = (view.panel_min().y + view.panel_max().y) / 2;
  s->input().push({TouchEvent::Kind::down, 0, cx, cy});
  for (int k = 0; k < 3; ++k) s->frame();
  float dx = 0;
  for (auto _ : state) {
    dx = dx > 200 ? -200 : dx + 4;  // back and forth: the view keeps turning
    s->input().push({TouchEvent::Kind::move, 0, cx + dx, cy});
    s->frame();
  }
  state.counters["drawn_triangles"] = view.drawn_triangles();
  state.counters["shown_triangles"] = static_cast<double>(view.display_mesh().triangle_count());
  s->input().push({TouchEvent::Kind::up, 0, cx + dx, cy});
  for (int k = 0; k < 3; ++k) s->frame();
}
BENCHMARK(BM_ModelTurning)
    ->Arg(200000)
    ->Arg(400000)
    ->Arg(1600000)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

// Pick + fit of one more tap on a trace of three (what the screen does
// between the release of the finger and the frame that shows the new dip),
// and that frame.
void BM_TapToDip(benchmark::State& state) {
  if (!have_ui_bench_project(state)) return;
  auto s = open(400000);
  s->tap("Mapping");
  const ModelView& view = s->state().model_view;
  const auto centre = view.to_screen(view.display_mesh().centre);
  TraceContext context;
  context.picker = view.picker();
  std::vector<ScreenRay> rays;
  for (int i = 0; i < 4; ++i)
    rays.push_back(view.ray_at(ImVec2(centre->x - 150 + 100 * i, centre->y - 60 + 40 * i)));
  for (auto _ : state) {
    state.PauseTiming();
    TraceMarker marker;
    for (int i = 0; i < 3; ++i) marker.tap({rays[i].origin, rays[i].direction}, context);
    state.ResumeTiming();
    marker.tap({rays[3].origin, rays[3].direction}, context);
    benchmark::DoNotOptimize(marker.plane());
  }
}
BENCHMARK(BM_TapToDip)->Unit(benchmark::kMillisecond);

void BM_StartUp(benchmark::State& state) {
  if (!have_ui_bench_project(state)) return;
  for (auto _ : state) {
    auto s = open(400000);
    benchmark::DoNotOptimize(s->state().model_view.has_model());
  }
}
BENCHMARK(BM_StartUp)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
