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
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
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

void merge(benchmark::State& state, const std::vector<double>& offsets) {
  std::vector<rp::FaceImage> images;
  try {
    for (double o : offsets)
      images.push_back(rt::face_image(pair_at(o), "station " + std::to_string(o) + " m"));
  } catch (const std::exception& e) {
    // A pair that sees too little of the 8.4 m face has no 3D image.
    state.SkipWithError(e.what());
    return;
  }
  const Eigen::Vector3d origin = rt::face_origin(pair_at(0.0));
  rp::FaceRegistration face;
  for (auto _ : state) {
    rockface::NoProgress progress;
    face = rp::register_face_images(images, {}, rp::preset_standard(), {}, progress);
  }
  double overlap = 0, tie_rms = 0, surface_rms = 0, truth_rms = 0;
  int tie_points = 1 << 30;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const rp::ImageResidual& r = face.images[i];
    if (i > 0) {
      overlap += r.overlap / static_cast<double>(images.size() - 1);
      tie_points = std::min(tie_points, r.tie_points);
      tie_rms = std::max(tie_rms, r.tie_rms_m);
      surface_rms = std::max(surface_rms, r.surface_rms_m);
    }
    double sum2 = 0;
    std::size_t n = 0;
    for (std::size_t v = 0; v < images[i].mesh.size(); v += 5) {
      const auto d = rt::distance_to_face(r.to_face.apply(images[i].mesh.vertices[v]) + origin);
      if (!d || *d > 0.5) continue;  // the pole, 3 m in front of the face, or off the facets
      sum2 += *d * *d;
      ++n;
    }
    if (n > 0) truth_rms = std::max(truth_rms, std::sqrt(sum2 / static_cast<double>(n)));
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
  state.counters["images"] = static_cast<double>(images.size());
  state.counters["spacing_m"] = offsets.size() > 1 ? std::abs(offsets[1]) : 0.0;
  state.counters["overlap"] = overlap;
  state.counters["tie_points"] = tie_points;
  state.counters["tie_rms_mm"] = tie_rms * 1000;
  state.counters["surface_rms_mm"] = surface_rms * 1000;
  state.counters["truth_rms_mm"] = truth_rms * 1000;
  state.counters["width_m"] = east - west;
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
    ->UseRealTime();

// Ten images, stations 0.5 m apart alternately West and East (the face's
// 8.4 m hold no more at 1 m): how the merge grows beyond five.
void BM_MergeTenImages(benchmark::State& state) {
  merge(state, {0.0, -0.5, 0.5, -1.0, 1.0, -1.5, 1.5, -2.0, 2.0, -2.5});
}
BENCHMARK(BM_MergeTenImages)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

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
    ->UseRealTime();

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
