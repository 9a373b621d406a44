// The drive of a project (`rockface drive`): 1,000 visits of synthetic
// records in a project file (18 measured planes each, three sets, one
// folding every 100 visits), read, clustered per visit, tracked along the
// drive, drawn and written as CSV. Issue 22's "drive plot time for 1,000
// visits".
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include <benchmark/benchmark.h>

#include "core/geometry/orientation.h"
#include "core/tunnel/design_profile.h"
#include "firmware-app/tunnel/project_drive.h"
#include "storage/field_report/tunnel_pictures.h"
#include "storage/project/project_store.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

fs::path make_project(int visits) {
  const fs::path file =
      fs::temp_directory_path() / ("rockface-drive-bench-" + std::to_string(::getpid()) + "-" +
                                   std::to_string(visits) + ".rockface");
  fs::remove(file);
  storage::ProjectInfo info;
  info.name = "drive bench";
  storage::ProjectStore store = storage::ProjectStore::create(file, info);
  storage::TunnelRecord tunnel;
  tunnel.name = "bench";
  tunnel.stations = {{0, {0, 0, 0}}, {4000, {0, 4000, 0}}};
  tunnel.radii = {0};
  tunnel.profile = tunnel::circle_profile(3.0);
  store.save_tunnel(tunnel);
  std::mt19937 rng(7);
  std::normal_distribution<double> jitter(0, 2.0);
  for (int i = 0; i < visits; ++i) {
    const storage::RecordId visit = store.begin_visit("bench");
    std::vector<storage::Measurement> planes;
    const double fold = 40 + 10 * ((i / 100) % 2);
    for (const auto& [dip, dipdir] :
         std::vector<std::pair<double, double>>{{70, 120}, {fold, 300}, {20, 30}})
      for (int k = 0; k < 6; ++k) {
        storage::Measurement m;
        m.visit_id = visit;
        m.label = "T" + std::to_string(planes.size() + 1);
        m.points = {{0, 3.0 * i, 0}, {1, 3.0 * i, 1}};
        m.dip_deg = std::clamp(dip + jitter(rng), 0.0, 90.0);
        m.dipdir_deg = std::fmod(dipdir + jitter(rng) + 360, 360);
        planes.push_back(m);
      }
    store.save_measurements(visit, planes);
    storage::VisitPlacement p;
    p.visit_id = visit;
    p.chainage = 3.0 * i;
    store.save_visit_placement(p);
  }
  return file;
}

void BM_ProjectDrive(benchmark::State& state) {
  const fs::path file = make_project(static_cast<int>(state.range(0)));
  storage::OpenOptions read;
  read.read_only = true;
  std::size_t tracks = 0;
  for (auto _ : state) {
    storage::ProjectStore store = storage::ProjectStore::open(file, read);
    const tunnel::DriveSets drive = app::project_drive(store);
    const cv::Mat picture = storage::drive_picture(drive);
    const std::string csv = app::drive_csv(drive, app::drive_geologists(store));
    benchmark::DoNotOptimize(picture.data);
    benchmark::DoNotOptimize(csv.data());
    tracks = drive.tracks.size();
  }
  state.counters["tracks"] = static_cast<double>(tracks);
  fs::remove(file);
}
BENCHMARK(BM_ProjectDrive)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(3);

// The picture alone, for the same drive.
void BM_DrivePicture(benchmark::State& state) {
  const fs::path file = make_project(static_cast<int>(state.range(0)));
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(file, read);
  const tunnel::DriveSets drive = app::project_drive(store);
  for (auto _ : state) {
    const cv::Mat picture = storage::drive_picture(drive);
    benchmark::DoNotOptimize(picture.data);
  }
  fs::remove(file);
}
BENCHMARK(BM_DrivePicture)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
