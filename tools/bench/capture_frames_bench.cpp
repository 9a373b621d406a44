// Issue 45: the Capture screen's frames while the queue of 3D images makes
// a 24 Mpx pair's 3D image beside it, as at the face, where the geologist
// shoots the next pair meanwhile. On the software renderer at 1280 x 800
// (Mesa's llvmpipe through surfaceless EGL, what a tablet without a working
// GPU driver runs), the UI thread's frame times idle and during the
// reconstruction at the standard preset (median, 95th percentile, the
// longest), and the reconstruction's wall time with the frames drawn beside
// it. The queue's worker is a thread of its own; on 2 cores it shares them
// with the renderer's threads and the UI thread, which is what is measured.
// Frames are paced as the tablet's window paces them (60 a second): drawn
// back to back (a third of a millisecond each), the headless frames took
// the cores from the reconstruction and made it 3-4 times slower, which
// is not what the tablet's window does.
//
// The project: the demo's (`tools/demo.sh` writes
// out/tunnel-face-demo.rockface, 6000 x 4000 pairs of the tunnel-face
// sample), copied to a temporary folder; set ROCKFACE_CAPTURE_BENCH_PROJECT
// to use another. Its first pair is reconstructed again.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "ui/platform/frame_pacer.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using Clock = std::chrono::steady_clock;

fs::path project_file() {
  if (const char* p = std::getenv("ROCKFACE_CAPTURE_BENCH_PROJECT")) return p;
  return fs::path(ROCKFACE_SOURCE_DIR) / "out/tunnel-face-demo.rockface";
}

// Frame times (ms): median, 95th percentile, longest.
struct FrameFigures {
  double median = 0, p95 = 0, longest = 0;
  std::size_t frames = 0;
};

FrameFigures figures_of(std::vector<double> ms) {
  FrameFigures f;
  f.frames = ms.size();
  if (ms.empty()) return f;
  std::sort(ms.begin(), ms.end());
  f.median = ms[ms.size() / 2];
  f.p95 = ms[std::min(ms.size() - 1, ms.size() * 95 / 100)];
  f.longest = ms.back();
  return f;
}

// One frame, paced as the tablet's window paces them (ui/platform/frame_pacer.h).
double frame_ms(ui::HeadlessSession& s, ui::FramePacer& pacer) {
  const auto from = Clock::now();
  s.frame();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - from).count();
  pacer.wait();
  return ms;
}

void BM_CaptureFramesWhileReconstructing(benchmark::State& state) {
  if (!fs::exists(project_file())) {
    state.SkipWithError(
        ("no project " + project_file().string() + " (see the bench's header)").c_str());
    return;
  }
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-capture-frames-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path project = dir / "frames.rockface";
  fs::copy_file(project_file(), project, fs::copy_options::overwrite_existing);
  storage::RecordId capture = 0;
  {
    auto store = storage::ProjectStore::open(project);
    const auto captures = store.list_captures();
    if (captures.empty()) {
      state.SkipWithError("the project holds no pair");
      return;
    }
    capture = captures.front().id;
  }

  FrameFigures idle, busy;
  double reconstruction_s = 0;
  for (auto _ : state) {
    app::FieldRunners runners{""};
    ui::FieldServices services = runners.services();
    services.camera = nullptr;
    services.sync = nullptr;
    ui::UiOptions options;
    options.project = project;
    ui::HeadlessSession s(options, services, 1280, 800);
    s.settle();
    s.tap("Capture");
    s.settle();
    ui::FramePacer pacer;
    std::vector<double> ms;
    for (int i = 0; i < 120; ++i) ms.push_back(frame_ms(s, pacer));
    idle = figures_of(ms);

    ms.clear();
    const auto from = Clock::now();
    s.state().reconstructions.add("3D image", [&runners, project, capture](Progress& progress) {
      runners.reconstruction.reconstruct(project, capture, Preset::standard, progress);
      return std::string("made");
    });
    while (s.state().reconstructions.busy()) ms.push_back(frame_ms(s, pacer));
    reconstruction_s = std::chrono::duration<double>(Clock::now() - from).count();
    busy = figures_of(ms);
  }
  state.counters["idle_median_ms"] = idle.median;
  state.counters["idle_p95_ms"] = idle.p95;
  state.counters["idle_longest_ms"] = idle.longest;
  state.counters["busy_median_ms"] = busy.median;
  state.counters["busy_p95_ms"] = busy.p95;
  state.counters["busy_longest_ms"] = busy.longest;
  state.counters["busy_frames"] = static_cast<double>(busy.frames);
  state.counters["reconstruction_s"] = reconstruction_s;
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}
BENCHMARK(BM_CaptureFramesWhileReconstructing)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
