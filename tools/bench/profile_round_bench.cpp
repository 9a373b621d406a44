// One round's over- and underbreak as `rockface profile` computes it (issue
// 38: the profile's time and ray count). The sample heading
// (tools/samples/tunnel-drive.scene.json, its alignment and profile) is
// replayed once at the standard preset through the mock camera; then
// - BM_ProfileRound/preset: visit_profile as the verb runs it (the tunnel
//   and the 3D image read from the project, the round found, the mesh's
//   ray caster built, the rays cast), at each preset's section and ray
//   spacing (0 fast, 1 standard, 2 precise);
// - BM_ProfileRays/preset: the rays alone, on a caster built once;
// - BM_LiningPair/lining: the heading's pair reconstructed at standard as a
//   face (0) and as a tunnel round (1: the pair padded and matched again by
//   slanted passes, preset.h's lining_along_the_drive, issue 38): the CPU
//   the lining's matching adds to a pair; counters: vertices of the 3D
//   image.
// Counters: rays cast, cells of the developed view, the share of them seen,
// the triangles, the volumes (so a change of cost can be read beside a
// change of result).
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/analysis/preset_options.h"
#include "core/common/progress.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "firmware-app/replay/field_replay.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "firmware-app/tunnel/visit_surface.h"
#include "storage/project/project_store.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

struct Replayed {
  fs::path dir, project;
  storage::RecordId visit = 0;
};

// The sample heading replayed once for every benchmark of the process.
const Replayed& sample_round() {
  static const Replayed r = [] {
    Replayed out;
    out.dir = fs::temp_directory_path() / ("rockface-profile-bench-" + std::to_string(::getpid()));
    fs::remove_all(out.dir);
    fs::create_directories(out.dir);
    const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
    std::ifstream in(samples / "tunnel-drive.scene.json");
    nlohmann::json s = nlohmann::json::parse(in);
    s["tunnel"]["alignment"] = (samples / "tunnel-drive.alignment.csv").string();
    s["tunnel"]["profile"] = (samples / "tunnel-drive.profile.json").string();
    const fs::path scene = out.dir / "sample.scene.json";
    std::ofstream(scene) << s.dump(2);
    out.project = out.dir / "sample.rockface";
    NoProgress quiet;
    out.visit = app::replay_field_workflow(
                    {scene.string(), out.project.string(), Preset::standard, {}, {}, {}}, quiet)
                    .visit_id;
    return out;
  }();
  return r;
}

void count(benchmark::State& state, const tunnel::ProfileDeviation& d) {
  state.counters["rays"] = static_cast<double>(d.rays_cast);
  state.counters["cells"] = static_cast<double>(d.view.state.size());
  state.counters["seen_pct"] = 100 * d.seen_fraction;
  state.counters["triangles"] = static_cast<double>(d.triangles);
  state.counters["over_m3"] = d.overbreak_volume_m3;
  state.counters["under_m3"] = d.underbreak_volume_m3;
}

void BM_ProfileRound(benchmark::State& state) {
  const Replayed& r = sample_round();
  const auto preset = static_cast<Preset>(state.range(0));
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(r.project, read);
  app::VisitProfile p;
  for (auto _ : state) {
    p = app::visit_profile(store, r.visit, preset);
    benchmark::DoNotOptimize(p.deviation.sections.data());
  }
  count(state, p.deviation);
}
BENCHMARK(BM_ProfileRound)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_ProfileRays(benchmark::State& state) {
  const Replayed& r = sample_round();
  const auto preset = static_cast<Preset>(state.range(0));
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(r.project, read);
  // The round and the options as visit_profile sets them.
  const app::VisitProfile round = app::visit_profile(store, r.visit, preset);
  const app::VisitSurface surface = app::visit_surface(store, r.visit);
  const tunnel::Alignment alignment = round.tunnel.alignment(store.project().datum);
  tunnel::DeviationOptions o = analysis::preset_options(preset).deviation;
  o.chainage_from = round.round_from;
  o.chainage_to = round.round_to;
  o.underbreak_tolerance_m = round.tunnel.underbreak_tolerance_m;
  if (surface.depth_sigma_m) o.depth_sigma_m = *surface.depth_sigma_m;
  const tunnel::MeshRaycaster caster(surface.vertices, surface.triangles);
  tunnel::ProfileDeviation d;
  for (auto _ : state) {
    d = tunnel::profile_deviation(caster, app::surface_input(surface), alignment,
                                  round.tunnel.profile, o);
    benchmark::DoNotOptimize(d.sections.data());
  }
  count(state, d);
}
BENCHMARK(BM_ProfileRays)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_LiningPair(benchmark::State& state) {
  const Replayed& r = sample_round();
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(r.project, read);
  const auto captures = store.list_captures(r.visit);
  const storage::Capture capture = store.load_capture(captures.front().id);
  const auto k = store.load_calibration(*capture.calibration_id).intrinsics;
  const cv::Mat left = cv::imdecode(capture.left.bytes, cv::IMREAD_COLOR);
  const cv::Mat right = cv::imdecode(capture.right.bytes, cv::IMREAD_COLOR);
  auto preset = analysis::preset_options(Preset::standard).reconstruction;
  preset.lining_along_the_drive = state.range(0) != 0;
  photogrammetry::ReconstructionResult rec;
  for (auto _ : state) {
    NoProgress quiet;
    rec = photogrammetry::reconstruct(left, right, k, k, preset, {}, quiet);
    benchmark::DoNotOptimize(rec.mesh.vertices.data());
  }
  state.counters["vertices"] = static_cast<double>(rec.mesh.size());
  state.counters["width_px"] = left.cols;
}
BENCHMARK(BM_LiningPair)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kSecond)
    ->Iterations(2)
    ->MeasureProcessCPUTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  fs::remove_all(fs::temp_directory_path() /
                 ("rockface-profile-bench-" + std::to_string(::getpid())));
  return 0;
}
