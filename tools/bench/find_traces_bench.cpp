// The tablet's Find traces as the geologist waits for it (issue 45: the
// first proposals within 2 s, the rest as they come): the Mapping screen on
// the model of a 24 Mpx pair, the program's own runners, frames drawn at the
// window's pace (ui/platform/frame_pacer.h, sixty a second, as
// run_in_window draws them) while the search runs on the worker beside
// them. Wall time from the tap to the first frame whose screen holds the
// first proposals, and to the frame that holds the whole result; the
// process's CPU over the same time; the frames drawn and how many of them
// the model renderer drew (a still model is not drawn again).
//
// The project: tools/bench/ui_bench_project.h (the figures in
// docs/accuracy-cost.md: the tunnel face replayed at standard). Find traces
// keeps its proposals in the session: the project is not changed.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <ctime>

#include "firmware-app/services/ui_services.h"
#include "tools/bench/ui_bench_project.h"
#include "ui/platform/frame_pacer.h"
#include "ui/platform/headless_session.h"

namespace {

using namespace rockface::ui;

double seconds_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double process_cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BM_FindTracesOnTheTablet(benchmark::State& state) {
  if (!have_ui_bench_project(state)) return;
  // Far more than the search takes on 2 cores: a stuck search, not a slow one.
  constexpr double kGiveUpS = 300;
  double first_s = 0, whole_s = 0, first_cpu_s = 0, whole_cpu_s = 0;
  long frames = 0, model_frames = 0, first_count = 0, whole_count = 0, screen_frames = 0;
  for (auto _ : state) {
    state.PauseTiming();
    rockface::app::FieldRunners runners{""};
    FieldServices services = runners.services();
    services.sync = nullptr;
    services.camera = nullptr;
    UiOptions options;
    options.project = ui_bench_project();
    HeadlessSession s(options, services, 1280, 800);
    s.settle();
    s.tap("Mapping");
    s.settle();
    if (!s.state().model_view.has_model()) {
      state.SkipWithError("the project's latest visit has no 3D image");
      return;
    }
    const ProposalsState& proposals = s.state().mapping.proposals;
    const long model_frames_from = s.state().model_view.frames_drawn();
    const long screen_frames_from = s.frames_drawn();
    state.ResumeTiming();
    const double from = seconds_now(), cpu_from = process_cpu_now();
    s.tap("Find traces");
    FramePacer pacer;
    frames = 0;
    first_s = 0;
    while (seconds_now() - from < kGiveUpS) {
      s.frame();
      ++frames;
      const bool shown = proposals.result && !proposals.result->proposals.empty();
      if (shown && first_s == 0) {
        first_s = seconds_now() - from;
        first_cpu_s = process_cpu_now() - cpu_from;
        first_count = static_cast<long>(proposals.result->proposals.size());
      }
      if (shown && !proposals.provisional && !s.state().task.running()) break;
      pacer.wait();
    }
    whole_s = seconds_now() - from;
    whole_cpu_s = process_cpu_now() - cpu_from;
    state.PauseTiming();
    if (first_s == 0 || proposals.provisional) {
      state.SkipWithError("no proposals within the time given");
      return;
    }
    whole_count = static_cast<long>(proposals.result->proposals.size());
    model_frames = s.state().model_view.frames_drawn() - model_frames_from;
    screen_frames = s.frames_drawn() - screen_frames_from;
    state.ResumeTiming();
  }
  state.counters["first_s"] = first_s;
  state.counters["first_cpu_s"] = first_cpu_s;
  state.counters["first_proposals"] = static_cast<double>(first_count);
  state.counters["whole_s"] = whole_s;
  state.counters["whole_cpu_s"] = whole_cpu_s;
  state.counters["proposals"] = static_cast<double>(whole_count);
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["model_frames_drawn"] = static_cast<double>(model_frames);
  state.counters["screen_frames_drawn"] = static_cast<double>(screen_frames);
}
BENCHMARK(BM_FindTracesOnTheTablet)->Unit(benchmark::kMillisecond)->Iterations(1);

// The Mapping screen on the same model with nothing happening: the CPU of
// a frame built (and drawn only when it shows something new), and how many
// of them were drawn.
void BM_MappingScreenStillFrame(benchmark::State& state) {
  if (!have_ui_bench_project(state)) return;
  UiOptions options;
  options.project = ui_bench_project();
  HeadlessSession s(options, FieldServices{}, 1280, 800);
  s.settle();
  s.tap("Mapping");
  s.settle();
  const long drawn_from = s.frames_drawn();
  const double cpu_from = process_cpu_now();
  long frames = 0;
  for (auto _ : state) {
    s.frame();
    ++frames;
  }
  state.counters["cpu_ms_per_frame"] = 1e3 * (process_cpu_now() - cpu_from) / frames;
  state.counters["screen_frames_drawn"] = static_cast<double>(s.frames_drawn() - drawn_from);
}
BENCHMARK(BM_MappingScreenStillFrame)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
