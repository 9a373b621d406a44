// Several 3D images of one face, and the field report: what merging costs.
//
// Merge: the synthetic face photographed as stereo pairs from stations moved
// along it (tests/integration_reconstruct/multi_image_face.h, 1200 x 800 px,
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
// Report: `rockface report` of the demo project (`rockface replay` of
// tools/samples/tunnel-face-demo.scene.json, made once into a temporary
// directory): reading the visit from the project, and writing the PDF.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/photogrammetry/estimators/multi_image_registration.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pdf.h"
#include "storage/project_store.h"
#include "tests/integration_reconstruct/multi_image_face.h"

namespace rp = rockface::photogrammetry;
namespace rt = rockface::testing;
namespace fs = std::filesystem;

namespace {

// One reconstructed pair per station offset (East, metres), made once.
const rt::FacePair& pair_at(double offset) {
  static std::map<double, rt::FacePair> cache;
  auto it = cache.find(offset);
  if (it == cache.end())
    it = cache
             .emplace(offset,
                      rt::photograph_and_reconstruct(rt::multi_image_face(offset), offset == 0.0))
             .first;
  return it->second;
}

std::vector<rp::FaceImage> face_images(const std::vector<double>& offsets) {
  std::vector<rp::FaceImage> images;
  for (double o : offsets)
    images.push_back(rt::face_image(pair_at(o), "station " + std::to_string(o) + " m"));
  return images;
}

// One merge: its wall and process CPU time (every thread), where the wall
// time went, and the residuals against the truth.
struct MergeRun {
  double wall_s = 0, cpu_s = 0;
  rp::MergeTimes times;
  double overlap = 0, tie_rms = 0, surface_rms = 0, truth_rms = 0, width = 0;
  int tie_points = 1 << 30;
};

double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double load_average() {
  double load = 0;
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = 0;
    std::fclose(f);
  }
  return load;
}

MergeRun run_merge(const std::vector<rp::FaceImage>& images,
                   const rp::MultiImageOptions& options = {}) {
  MergeRun run;
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_s();
  rockface::NoProgress progress;
  const rp::FaceRegistration face =
      rp::register_face_images(images, {}, rp::preset_standard(), options, progress);
  run.cpu_s = process_cpu_s() - cpu0;
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  run.times = face.times;
  const Eigen::Vector3d origin = rt::face_origin(pair_at(0.0));
  for (std::size_t i = 0; i < images.size(); ++i) {
    const rp::ImageResidual& r = face.images[i];
    if (i > 0) {
      run.overlap += r.overlap / static_cast<double>(images.size() - 1);
      run.tie_points = std::min(run.tie_points, r.tie_points);
      run.tie_rms = std::max(run.tie_rms, r.tie_rms_m);
      run.surface_rms = std::max(run.surface_rms, r.surface_rms_m);
    }
    double sum2 = 0;
    std::size_t n = 0;
    for (std::size_t v = 0; v < images[i].mesh.size(); v += 5) {
      const auto d = rt::distance_to_face(r.to_face.apply(images[i].mesh.vertices[v]) + origin);
      if (!d || *d > 0.5) continue;  // the pole, 3 m in front of the face, or off the facets
      sum2 += *d * *d;
      ++n;
    }
    if (n > 0) run.truth_rms = std::max(run.truth_rms, std::sqrt(sum2 / static_cast<double>(n)));
  }
  const rp::SurfaceMesh merged = rp::merged_surface(images, face);
  double west = 1e9, east = -1e9;
  for (const auto& v : merged.vertices) {
    const Eigen::Vector3d w = v + origin;
    const auto d = rt::distance_to_face(w);
    if (!d || *d > 0.5) continue;
    west = std::min(west, w.x());
    east = std::max(east, w.x());
  }
  run.width = east - west;
  return run;
}

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

// 2, 5 and 10 images interleaved: round after round each merge runs once, in
// an order that turns by one each round, so that the load of a shared
// machine falls on all of them alike; medians over the rounds, with the
// spread (min and max) and the process CPU time (all threads). One cold run
// of each comes first and is not counted (first-call allocations, OpenCV's
// and TBB's thread pools); the 2-image one is reported as cold2_s. The ratio
// of the medians and the median of each round's own ratio are both given.
// At the tie points' SIFT width of the default (600 px) and of the
// photographs' own (1200 px, the preset's, which the merge used before).
// One line per round goes to stderr.
void BM_MergeInterleaved(benchmark::State& state) {
  const std::vector<std::vector<double>> offsets{
      {0.0, -1.0},
      {0.0, -1.0, 1.0, -2.0, 2.0},
      {0.0, -0.5, 0.5, -1.0, 1.0, -1.5, 1.5, -2.0, 2.0, -2.5}};
  const std::vector<std::string> names{"2", "5", "10"};
  std::vector<std::vector<rp::FaceImage>> images;
  for (const auto& o : offsets) images.push_back(face_images(o));
  const auto rounds = static_cast<std::size_t>(state.range(0));
  rp::MultiImageOptions options;
  options.feature_max_width = static_cast<int>(state.range(1));
  std::vector<std::vector<MergeRun>> runs(images.size());
  double load_min = 1e9, load_max = 0;
  for (auto _ : state) {
    state.counters["cold2_s"] = run_merge(images[0], options).wall_s;
    for (std::size_t k = 1; k < images.size(); ++k) run_merge(images[k], options);
    for (std::size_t r = 0; r < rounds; ++r) {
      const double load = load_average();
      load_min = std::min(load_min, load);
      load_max = std::max(load_max, load);
      std::fprintf(stderr, "round %zu (load %.1f):", r + 1, load);
      for (std::size_t m = 0; m < images.size(); ++m) {
        const std::size_t k = (m + r) % images.size();
        runs[k].push_back(run_merge(images[k], options));
        std::fprintf(stderr, "  %s images %.2f s (CPU %.2f s)", names[k].c_str(),
                     runs[k].back().wall_s, runs[k].back().cpu_s);
      }
      std::fprintf(stderr, "\n");
    }
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t h = v.size() / 2;
    return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
  };
  auto column = [&](std::size_t k, auto get) {
    std::vector<double> v;
    for (const auto& run : runs[k]) v.push_back(get(run));
    return v;
  };
  auto wall = [](const MergeRun& x) { return x.wall_s; };
  auto cpu = [](const MergeRun& x) { return x.cpu_s; };
  std::vector<double> medians;
  for (std::size_t k = 0; k < images.size(); ++k) {
    const std::vector<double> w = column(k, wall);
    medians.push_back(median(w));
    state.counters["t" + names[k] + "_s"] = medians.back();
    state.counters["t" + names[k] + "_min_s"] = *std::min_element(w.begin(), w.end());
    state.counters["t" + names[k] + "_max_s"] = *std::max_element(w.begin(), w.end());
    state.counters["cpu" + names[k] + "_s"] = median(column(k, cpu));
    // The residuals of every round, worst and best: equal when the merge is deterministic.
    const std::vector<double> truth = column(k, [](const MergeRun& x) { return x.truth_rms; });
    state.counters["truth" + names[k] + "_mm"] =
        1000 * *std::max_element(truth.begin(), truth.end());
    state.counters["truth" + names[k] + "_best_mm"] =
        1000 * *std::min_element(truth.begin(), truth.end());
    const std::vector<double> surface = column(k, [](const MergeRun& x) { return x.surface_rms; });
    state.counters["surface" + names[k] + "_mm"] =
        1000 * *std::max_element(surface.begin(), surface.end());
  }
  for (std::size_t k = 1; k < images.size(); ++k) {
    std::vector<double> paired;
    for (std::size_t r = 0; r < rounds; ++r)
      paired.push_back(runs[k][r].wall_s / runs[0][r].wall_s);
    state.counters["ratio" + names[k]] = medians[k] / medians[0];
    state.counters["ratio" + names[k] + "_paired"] = median(paired);
    state.counters["ratio" + names[k] + "_min"] = *std::min_element(paired.begin(), paired.end());
    state.counters["ratio" + names[k] + "_max"] = *std::max_element(paired.begin(), paired.end());
  }
  state.counters["load_min"] = load_min;
  state.counters["load_max"] = load_max;
}
BENCHMARK(BM_MergeInterleaved)
    ->ArgNames({"rounds", "width"})
    ->Args({5, 600})
    ->Args({5, 1200})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

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
