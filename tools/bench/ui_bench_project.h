#pragma once
// The project the tablet's benchmarks open (ui_bench, find_traces_bench):
// `rockface replay tools/samples/tunnel-face.scene.json --preset fast
// --project out/tunnel-face-24mpx.rockface`, or ROCKFACE_UI_BENCH_PROJECT.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

inline std::filesystem::path ui_bench_project() {
  if (const char* p = std::getenv("ROCKFACE_UI_BENCH_PROJECT")) return p;
  return std::filesystem::path(ROCKFACE_SOURCE_DIR) / "out/tunnel-face-24mpx.rockface";
}

// False, and the benchmark skipped saying why, when the project is missing.
inline bool have_ui_bench_project(benchmark::State& state) {
  if (std::filesystem::exists(ui_bench_project())) return true;
  state.SkipWithError(
      ("no project " + ui_bench_project().string() + " (see the bench's header)").c_str());
  return false;
}
