// Reconstruction: what accuracy costs. The synthetic faceted face
// (tests/support/synthetic_face.h) rendered at 6 and 24 Mpx,
// reconstructed with each preset and with the image-scale and disparity
// knobs of the standard preset; errors against the render's truth. Dense
// matching alone on the Middlebury Rocks pairs against their true
// disparities. Peak memory is the process's maximum resident set: run one
// case per process (tools/bench/run_reconstruct.sh) for per-case figures.
//
// Counters: points, rot_err_deg (relative orientation), facet_err_deg (worst
// facet normal), scale_err_pct, north_err_deg, peak_rss_MB; Middlebury:
// bad2_pct (|error| > 2 px among matched pixels), mean_err_px, density_pct.
#include <sys/resource.h>

#include <map>
#include <string>

#include <benchmark/benchmark.h>
#include <opencv2/imgcodecs.hpp>

#include "core/common/preset.h"
#include "core/photogrammetry/matching/dense_matching.h"
#include "tests/support/synthetic_truth.h"

namespace rp = rockface::photogrammetry;

namespace {

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kB on Linux
}

struct Rendered {
  rockface::camera::SyntheticScene scene;
  rockface::camera::SyntheticRender render;
};

const Rendered& rendered(int width) {
  static std::map<int, Rendered> cache;
  auto it = cache.find(width);
  if (it == cache.end()) {
    Rendered r;
    r.scene = rockface::testing::synthetic_face(width, width * 2 / 3, true, 2.0);
    rockface::NoProgress progress;
    r.render = rockface::camera::render_scene(r.scene, progress);
    it = cache.emplace(width, std::move(r)).first;
  }
  return it->second;
}

void reconstruct_face(benchmark::State& state, const std::string& preset_name, int width,
                      int dense_max_width, int max_disparities) {
  const Rendered& r = rendered(width);
  rp::ReconstructionPreset preset =
      rp::reconstruction_preset(rockface::parse_preset(preset_name, "bench preset"));
  if (dense_max_width > 0) preset.dense_max_width = dense_max_width;
  if (max_disparities > 0) preset.max_disparities = max_disparities;
  const auto sources = rockface::testing::pole_and_compass(r.scene, r.render, 4.0);
  rp::ReconstructionResult result;
  for (auto _ : state) {
    rockface::NoProgress progress;
    result = rp::reconstruct(r.render.images[0], r.render.images[1], r.render.intrinsics,
                             r.render.intrinsics, preset, sources, progress);
  }
  const auto truth = rockface::testing::compare_with_truth(r.scene, r.render, result);
  state.counters["points"] = static_cast<double>(result.mesh.size());
  state.counters["rot_err_deg"] = truth.rotation_error_deg;
  state.counters["facet_err_deg"] = truth.worst_facet_deg;
  state.counters["scale_err_pct"] = 100 * truth.scale_error;
  state.counters["north_err_deg"] = truth.north_error_deg;
  state.counters["sigma_z_mm"] = 1000 * result.accuracy.sigma_z;
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

void middlebury(benchmark::State& state, const std::string& preset_name, const std::string& pair) {
  const std::string dir = std::string(ROCKFACE_SHARED_DIR) + "/data/middlebury-rocks/" + pair;
  const cv::Mat left = cv::imread(dir + "/view1.png"), right = cv::imread(dir + "/view5.png");
  const cv::Mat truth = cv::imread(dir + "/disp1.png", cv::IMREAD_GRAYSCALE);
  if (left.empty() || truth.empty()) {
    state.SkipWithError("Middlebury data not found");
    return;
  }
  // As the realdata test and the pipeline set it: the true range (0 .. 57 px
  // for both pairs) widened by 8 px, rounded up to a multiple of 16.
  double max_true = 0;
  cv::minMaxLoc(truth, nullptr, &max_true);
  const rp::DisparityRange range{0, ((static_cast<int>(max_true / 3.0) + 8 + 15) / 16) * 16};
  const rp::ReconstructionPreset preset =
      rp::reconstruction_preset(rockface::parse_preset(preset_name, "bench preset"));
  rp::DisparityMap map;
  for (auto _ : state) {
    rockface::NoProgress progress;
    map = rp::match_rectified(left, right, range, preset, progress);
  }
  std::size_t known = 0, matched = 0, bad = 0;
  double sum = 0;
  for (int y = 0; y < truth.rows; ++y)
    for (int x = 0; x < truth.cols; ++x) {
      const int t = truth.at<uchar>(y, x);
      if (t == 0) continue;
      ++known;
      const float d = map.disparity.at<float>(y, x);
      if (std::isnan(d)) continue;
      ++matched;
      const double e = std::abs(d - t / 3.0);
      sum += e;
      bad += e > 2.0;
    }
  state.counters["bad2_pct"] = matched ? 100.0 * bad / matched : 100.0;
  state.counters["mean_err_px"] = matched ? sum / matched : 0.0;
  state.counters["density_pct"] = known ? 100.0 * matched / known : 0.0;
}

}  // namespace

// Presets on a 6 Mpx pair (3000 x 2000) with distortion, noise and blur.
BENCHMARK_CAPTURE(reconstruct_face, fast_6Mpx, "fast", 3000, 0, 0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(reconstruct_face, standard_6Mpx, "standard", 3000, 0, 0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(reconstruct_face, precise_6Mpx, "precise", 3000, 0, 0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// The image-scale knob of the standard preset.
BENCHMARK_CAPTURE(reconstruct_face, standard_dense750_6Mpx, "standard", 3000, 750, 0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(reconstruct_face, standard_dense3000_6Mpx, "standard", 3000, 3000, 0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// The disparity-search knob: a cap below the scene's range truncates it.
BENCHMARK_CAPTURE(reconstruct_face, standard_disp64_6Mpx, "standard", 3000, 0, 64)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// A full 24 Mpx frame (6000 x 4000): memory stays bounded by the preset's scale.
BENCHMARK_CAPTURE(reconstruct_face, standard_24Mpx, "standard", 6000, 0, 0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

BENCHMARK_CAPTURE(middlebury, fast_Rocks1, "fast", "Rocks1")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(middlebury, standard_Rocks1, "standard", "Rocks1")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(middlebury, precise_Rocks1, "precise", "Rocks1")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(middlebury, fast_Rocks2, "fast", "Rocks2")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(middlebury, standard_Rocks2, "standard", "Rocks2")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(middlebury, precise_Rocks2, "precise", "Rocks2")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
