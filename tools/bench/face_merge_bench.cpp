// Several 3D images of one face, and the field report: what merging costs.
//
// Merge: the synthetic face photographed as stereo pairs from stations moved
// along it (tests/support/multi_image_face.h, 1200 x 800 px,
// standard preset); the middle pair is registered by range pole and compass,
// the others are registered to it (photogrammetry::register_face_images: SIFT
// tie points, similarity, ICP). Timed: the registration alone (the pairs are
// reconstructed once, before). Against the number of images (stations 1 m
// apart) and against the overlap (two images, stations 1 to 3.5 m apart).
// Counters: overlap (mean over the registered images, fraction of each
// surface on its reference), tie_points (fewest), tie_rms_mm and
// surface_rms_mm (worst image), truth_rms_mm (worst image's RMS distance to
// the true face, after registration), width_m (East extent of the merged face).
//
// The 2, 5 and 10-image merges interleaved, with their ratios:
// face_merge_ratio_bench.cpp (tools/bench/face_merge_ratio.sh).
//
// Report: `rockface report` of the demo project (`rockface replay` of
// tools/samples/tunnel-face-demo.scene.json, made once into a temporary
// directory): reading the visit from the project, and writing the PDF.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pdf.h"
#include "storage/project/project_store.h"
#include "tools/bench/face_merge_runs.h"

namespace rp = rockface::photogrammetry;
namespace fs = std::filesystem;
using rockface::bench::face_images;
using rockface::bench::load_average;
using rockface::bench::MergeRun;
using rockface::bench::run_merge;

namespace {

void residual_counters(benchmark::State& state, const MergeRun& run, const std::string& suffix) {
  state.counters["overlap" + suffix] = run.overlap;
  state.counters["tie_points" + suffix] = run.tie_points;
  state.counters["tie_rms_mm" + suffix] = run.tie_rms * 1000;
  state.counters["surface_rms_mm" + suffix] = run.surface_rms * 1000;
  state.counters["truth_rms_mm" + suffix] = run.truth_rms * 1000;
  state.counters["width_m" + suffix] = run.width;
}

// The stages of the last run (wall seconds, MergeTimes): the waves' sum,
// and per registered image the sum over images of each of its stages.
void stage_counters(benchmark::State& state, const rp::MergeTimes& t) {
  auto sum = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); };
  state.counters["prepare_s"] = t.prepare_s;
  state.counters["sift_s"] = t.features_s;
  state.counters["thumbs_s"] = t.thumbnails_s;
  state.counters["waves"] = static_cast<double>(t.waves_s.size());
  state.counters["waves_s"] = sum(t.waves_s);
  state.counters["match_s"] = sum(t.match_s);
  state.counters["ransac_s"] = sum(t.ransac_s);
  state.counters["surface_s"] = sum(t.surface_s);
  state.counters["total_s"] = t.total_s;
  // The same in CPU time (MergeTimes): the work, whatever the load.
  state.counters["sift_prep_cpu_s"] = t.features_cpu_s;
  state.counters["match_cpu_s"] = sum(t.match_cpu_s);
  state.counters["surface_cpu_s"] = sum(t.surface_cpu_s);
  state.counters["total_cpu_s"] = t.total_cpu_s;
}

void merge(benchmark::State& state, const std::vector<double>& offsets,
           const rp::MultiImageOptions& options = {}) {
  std::vector<rp::FaceImage> images;
  try {
    images = face_images(offsets);
  } catch (const std::exception& e) {
    // A pair that sees too little of the 8.4 m face has no 3D image.
    state.SkipWithError(e.what());
    return;
  }
  // The process's first merge pays OpenCV's and TBB's thread pools and
  // first allocations (5 s against 1.5 s for two images here): run once
  // untimed so that no row carries it.
  static bool warm = false;
  if (!warm) {
    run_merge(images, options);
    warm = true;
  }
  MergeRun run;
  const double load_before = load_average();
  double cpu = 0;
  for (auto _ : state) {
    run = run_merge(images, options);
    // The registration alone: the residuals against the truth are not timed.
    state.SetIterationTime(run.wall_s);
    cpu += run.cpu_s;
  }
  state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
  state.counters["load"] = 0.5 * (load_before + load_average());
  state.counters["images"] = static_cast<double>(images.size());
  state.counters["spacing_m"] = offsets.size() > 1 ? std::abs(offsets[1]) : 0.0;
  residual_counters(state, run, "");
  stage_counters(state, run.times);
}

// Images: stations 1 m apart, alternately West and East of the master.
void BM_MergeImages(benchmark::State& state) {
  const std::vector<double> all{0.0, -1.0, 1.0, -2.0, 2.0};
  merge(state, std::vector<double>(all.begin(), all.begin() + state.range(0)));
}
BENCHMARK(BM_MergeImages)
    ->ArgName("images")
    ->DenseRange(2, 5)
    ->Iterations(2)
    ->Unit(benchmark::kSecond)
    ->UseManualTime();

// Ten images, stations 0.5 m apart alternately West and East (the face's
// 8.4 m hold no more at 1 m): how the merge grows beyond five.
void BM_MergeTenImages(benchmark::State& state) {
  merge(state, {0.0, -0.5, 0.5, -1.0, 1.0, -1.5, 1.5, -2.0, 2.0, -2.5});
}
BENCHMARK(BM_MergeTenImages)->Iterations(1)->Unit(benchmark::kSecond)->UseManualTime();

// The width the tie points' SIFT is detected at (MultiImageOptions::
// feature_max_width; 1200 = the photographs' own), 2 and 5 images: what the
// registration's accuracy and time owe to it.
void BM_MergeFeatureWidth(benchmark::State& state) {
  const std::vector<double> all{0.0, -1.0, 1.0, -2.0, 2.0};
  rp::MultiImageOptions options;
  options.feature_max_width = static_cast<int>(state.range(1));
  merge(state, std::vector<double>(all.begin(), all.begin() + state.range(0)), options);
  state.counters["feature_width"] = static_cast<double>(state.range(1));
}
BENCHMARK(BM_MergeFeatureWidth)
    ->ArgNames({"images", "width"})
    ->ArgsProduct({{2, 5}, {1200, 800, 600, 400}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseManualTime();

// Overlap: two images, the second station `range(0)` cm West of the master
// (beyond 3 m its photographs show too little of the 8.4 m face for a 3D image).
void BM_MergeOverlap(benchmark::State& state) {
  merge(state, {0.0, -static_cast<double>(state.range(0)) / 100.0});
}
BENCHMARK(BM_MergeOverlap)
    ->ArgName("spacing_cm")
    ->Arg(100)
    ->Arg(200)
    ->Arg(250)
    ->Arg(300)
    ->Iterations(2)
    ->Unit(benchmark::kSecond)
    ->UseManualTime();

// The demo project, made once by the rockface binary.
const fs::path& demo_project() {
  static const fs::path project = [] {
    const fs::path dir =
        fs::temp_directory_path() / ("rockface-report-bench-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "demo.rockface";
    const std::string cmd = std::string(ROCKFACE_BINARY_DIR) + "/rockface replay " +
                            ROCKFACE_SOURCE_DIR + "/tools/samples/tunnel-face-demo.scene.json" +
                            " --project " + file.string() + " >/dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("failed: " + cmd);
    return file;
  }();
  return project;
}

rockface::storage::ProjectStore open_demo() {
  rockface::storage::OpenOptions options;
  options.read_only = true;
  return rockface::storage::ProjectStore::open(demo_project(), options);
}

void BM_ReportCollect(benchmark::State& state) {
  auto store = open_demo();
  std::size_t blocks = 0;
  for (auto _ : state) {
    const auto report = rockface::storage::collect_field_report(store, 1);
    blocks = report.blocks.size();
    benchmark::DoNotOptimize(report.photograph.data);
  }
  state.counters["blocks"] = static_cast<double>(blocks);
}
BENCHMARK(BM_ReportCollect)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReportPdf(benchmark::State& state) {
  auto store = open_demo();
  const auto report = rockface::storage::collect_field_report(store, 1);
  const fs::path pdf = demo_project().parent_path() / "report.pdf";
  for (auto _ : state) rockface::storage::write_field_report_pdf(report, pdf);
  state.counters["pdf_kB"] = static_cast<double>(fs::file_size(pdf)) / 1024.0;
}
BENCHMARK(BM_ReportPdf)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
