// Project store: what keeping a field day in one SQLite file costs.
// - save and load of a capture with two 24 Mpx JPEGs (textured, 8-12 MB each,
//   like a DSLR's), against the alternative of two plain files beside the
//   project;
// - save and load of a reconstructed model (1 M vertices, 2 M triangles, with
//   texture coordinates and colours);
// - opening a project (the read-only quick_check / integrity_check that
//   guards against damaged files) as the project grows;
// - project bytes per capture.
// Every save is durable when it returns (WAL, synchronous = FULL), as in the
// field. Run: build/<dir>/bench/project_store_bench (RelWithDebInfo or Release).
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "storage/project/project_store.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface::storage;

// A rock-face-like 6000 x 4000 photograph: smooth structure at several scales
// plus fine grain and sensor noise, JPEG quality 95 (a DSLR's "fine").
std::vector<std::uint8_t> dslr_jpeg(int seed) {
  constexpr int kWidth = 6000, kHeight = 4000;
  cv::RNG rng(static_cast<std::uint64_t>(seed) + 7);
  cv::Mat image(kHeight, kWidth, CV_32FC3, cv::Scalar::all(30));
  for (int scale : {400, 100, 25, 6, 2}) {
    cv::Mat coarse(kHeight / scale, kWidth / scale, CV_32FC3);
    rng.fill(coarse, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(scale >= 25 ? 70 : 28));
    cv::Mat up;
    cv::resize(coarse, up, image.size(), 0, 0, cv::INTER_CUBIC);
    image += up;
  }
  cv::Mat noise(image.size(), CV_32FC3);
  rng.fill(noise, cv::RNG::NORMAL, cv::Scalar::all(0), cv::Scalar::all(3));
  image += noise;
  cv::Mat bytes8;
  image.convertTo(bytes8, CV_8UC3);
  std::vector<std::uint8_t> out;
  cv::imencode(".jpg", bytes8, out, {cv::IMWRITE_JPEG_QUALITY, 95});
  return out;
}

const std::vector<std::uint8_t>& left_jpeg() {
  static const auto bytes = dslr_jpeg(1);
  return bytes;
}
const std::vector<std::uint8_t>& right_jpeg() {
  static const auto bytes = dslr_jpeg(2);
  return bytes;
}

// The same pair made distinct per save (identical images are stored once):
// a few bytes after the end-of-image marker, which decoders ignore.
Capture capture_pair(RecordId visit, int n) {
  Capture c;
  c.visit_id = visit;
  c.label = "pair " + std::to_string(n);
  c.left.bytes = left_jpeg();
  c.right.bytes = right_jpeg();
  for (int i = 0; i <= n % 97; ++i) {
    c.left.bytes.push_back(static_cast<std::uint8_t>(n));
    c.right.bytes.push_back(static_cast<std::uint8_t>(n + 1));
  }
  c.left.bytes.push_back(static_cast<std::uint8_t>(n / 97));
  c.settings = {{"iso", "200"}, {"shutter", "1/125"}, {"aperture", "f/8"}};
  c.left_exif = {{"Make", "Nikon"}, {"Model", "D7500"}};
  return c;
}

Model dense_model(std::optional<RecordId> capture) {
  constexpr int kSide = 1000;  // 1 M vertices, 2 M triangles
  Model m;
  m.capture_id = capture;
  m.preset = "standard";
  m.mesh.vertices.reserve(kSide * kSide);
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      m.mesh.vertices.emplace_back(0.005 * i, 8.0 + 0.01 * std::sin(0.05 * i + 0.03 * j),
                                   0.005 * j);
      m.mesh.texcoords.push_back({i / float(kSide), j / float(kSide)});
      m.mesh.colours.push_back({static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j), 90});
    }
  for (int j = 0; j + 1 < kSide; ++j)
    for (int i = 0; i + 1 < kSide; ++i) {
      const int a = j * kSide + i;
      m.mesh.faces.push_back({a, a + 1, a + kSide + 1});
      m.mesh.faces.push_back({a, a + kSide + 1, a + kSide});
    }
  if (capture) {
    m.texture_capture_id = capture;
    m.texture_side = "left";
  }
  m.registration.kind = "range_pole_compass";
  return m;
}

fs::path bench_dir() {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-store-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

ProjectInfo project_info() {
  ProjectInfo p;
  p.name = "benchmark";
  p.datum = {2690000, 1170000, 1100};
  return p;
}

void BM_SaveCapturePair24Mpx(benchmark::State& state) {
  const fs::path dir = bench_dir();
  const fs::path file = dir / "save.rockface";
  fs::remove(file);
  auto store = ProjectStore::create(file, project_info());
  const RecordId visit = store.begin_visit("bench");
  store.checkpoint();
  const auto empty_size = fs::file_size(file);
  int n = 0;
  std::int64_t image_bytes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const Capture c = capture_pair(visit, n++);
    image_bytes += static_cast<std::int64_t>(c.left.bytes.size() + c.right.bytes.size());
    state.ResumeTiming();
    store.save_capture(c);
  }
  store.checkpoint();
  const double per_capture = double(fs::file_size(file) - empty_size) / n;
  state.counters["jpeg_MB_per_capture"] = double(image_bytes) / n / 1e6;
  state.counters["project_MB_per_capture"] = per_capture / 1e6;
  state.counters["overhead_pct"] = 100.0 * (per_capture * n / double(image_bytes) - 1.0);
  state.SetBytesProcessed(image_bytes);
  fs::remove_all(dir);
}
BENCHMARK(BM_SaveCapturePair24Mpx)->Iterations(8)->Unit(benchmark::kMillisecond)->UseRealTime();

// The alternative: the two JPEGs as files beside the project, each fsynced,
// plus the folder (what a save would need to be as durable).
void BM_SavePairAsTwoFilesBeside(benchmark::State& state) {
  const fs::path dir = bench_dir();
  int n = 0;
  std::int64_t image_bytes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const Capture c = capture_pair(1, n++);
    state.ResumeTiming();
    for (const auto* side : {&c.left, &c.right}) {
      const fs::path f =
          dir / ("pair" + std::to_string(n) + (side == &c.left ? "L" : "R") + ".jpg");
      const int fd = ::open(f.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (::write(fd, side->bytes.data(), side->bytes.size()) < 0) state.SkipWithError("write");
      ::fsync(fd);
      ::close(fd);
      image_bytes += static_cast<std::int64_t>(side->bytes.size());
    }
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    ::fsync(dfd);
    ::close(dfd);
  }
  state.SetBytesProcessed(image_bytes);
  fs::remove_all(dir);
}
BENCHMARK(BM_SavePairAsTwoFilesBeside)->Iterations(8)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LoadCapturePair24Mpx(benchmark::State& state) {
  const fs::path dir = bench_dir();
  const fs::path file = dir / "load.rockface";
  RecordId id = 0;
  {
    auto store = ProjectStore::create(file, project_info());
    const RecordId visit = store.begin_visit("bench");
    for (int i = 0; i < 3; ++i) id = store.save_capture(capture_pair(visit, i));
  }
  auto store = ProjectStore::open(file);
  std::int64_t bytes = 0;
  for (auto _ : state) {
    const Capture c = store.load_capture(id);
    bytes += static_cast<std::int64_t>(c.left.bytes.size() + c.right.bytes.size());
    benchmark::DoNotOptimize(c.left.bytes.data());
  }
  state.SetBytesProcessed(bytes);
  fs::remove_all(dir);
}
BENCHMARK(BM_LoadCapturePair24Mpx)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SaveModel1MVertices(benchmark::State& state) {
  const fs::path dir = bench_dir();
  const fs::path file = dir / "model.rockface";
  auto store = ProjectStore::create(file, project_info());
  const RecordId visit = store.begin_visit("bench");
  const RecordId capture = store.save_capture(capture_pair(visit, 0));
  const Model model = dense_model(capture);
  store.checkpoint();
  const auto before = fs::file_size(file);
  int n = 0;
  for (auto _ : state) {
    store.save_model(model);
    ++n;
  }
  store.checkpoint();
  state.counters["project_MB_per_model"] = double(fs::file_size(file) - before) / n / 1e6;
  fs::remove_all(dir);
}
BENCHMARK(BM_SaveModel1MVertices)->Iterations(4)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LoadModel1MVertices(benchmark::State& state) {
  const fs::path dir = bench_dir();
  const fs::path file = dir / "model.rockface";
  RecordId id = 0;
  {
    auto store = ProjectStore::create(file, project_info());
    id = store.save_model(dense_model(std::nullopt));
  }
  auto store = ProjectStore::open(file);
  for (auto _ : state) {
    const Model m = store.load_model(id);
    benchmark::DoNotOptimize(m.mesh.vertices.data());
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_LoadModel1MVertices)->Iterations(4)->Unit(benchmark::kMillisecond)->UseRealTime();

// Opening a project of state.range(0) captures (each with its 24 Mpx pair):
// the read-only check before the file is trusted, quick or full.
void BM_OpenProject(benchmark::State& state) {
  const fs::path dir = bench_dir();
  const fs::path file = dir / "open.rockface";
  {
    auto store = ProjectStore::create(file, project_info());
    const RecordId visit = store.begin_visit("bench");
    for (int i = 0; i < state.range(0); ++i) store.save_capture(capture_pair(visit, i));
  }
  OpenOptions options;
  options.check = state.range(1) ? OpenOptions::Check::full : OpenOptions::Check::quick;
  for (auto _ : state) {
    auto store = ProjectStore::open(file, options);
    benchmark::DoNotOptimize(store.schema_version());
  }
  state.counters["project_MB"] = double(fs::file_size(file)) / 1e6;
  state.SetLabel(state.range(1) ? "integrity_check" : "quick_check");
  fs::remove_all(dir);
}
BENCHMARK(BM_OpenProject)
    ->ArgsProduct({{1, 10}, {0, 1}})
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
