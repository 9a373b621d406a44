// The office server (issue 24) on a real PostgreSQL server started here
// (tests/support/postgres_server.h, Unix socket, fsync off as the test
// fixture runs it: the times are the client's and the server's work, not
// the disk's): sync time and bytes per visit for one visit with two 24 Mpx
// photographs and a 3D image, and for 1,000 synthetic visits; the second
// sync of an unchanged project; the office's drive query over 3,000
// visits of three tablets (target: under a second); the rock mass and
// support of every round of a drive of 300 and 3,000 visits.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>

#include "core/common/progress.h"
#include "core/tunnel/design_profile.h"
#include "firmware-app/office/office_workflows.h"
#include "firmware-app/support/support_drive.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_schema.h"
#include "storage/office/sqlite_rows.h"
#include "storage/office/sync_push.h"
#include "storage/project/project_store.h"
#include "tests/support/postgres_server.h"
#include "tests/support/sample_records.h"
#include "tools/bench/bench_tablet_projects.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
namespace office = storage::office;

test::PostgresServer& server() {
  static test::PostgresServer s;
  return s;
}

fs::path folder() {
  static const fs::path dir =
      fs::temp_directory_path() / ("rockface-office-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string fresh_database() {
  static int n = 0;
  const std::string db = "bench" + std::to_string(++n);
  server().psql("CREATE DATABASE " + db, "postgres");
  office::Connection c(server().socket_conninfo(test::PostgresServer::kSuperuser, db));
  office::init_server(c);
  office::add_tunnel(c, "bench");
  for (const char* t : {"tablet_1", "tablet_2", "tablet_3"}) office::add_tablet(c, t, "bench");
  office::add_office_user(c, "office_bench");
  return db;
}

// A 3D image of about `vertices` vertices: a rough face on a grid.
storage::Model grid_model(storage::RecordId capture, int side) {
  return bench::grid_model(capture, side, "standard");
}

// The tablets' projects (tools/bench/bench_tablet_projects.h) in this
// benchmark's folder, with its 3D image.
fs::path make_project(const std::string& name, int visits, int width, int height, int mesh_side) {
  return bench::make_bench_project(folder(), name, visits, width, height, mesh_side, grid_model);
}

fs::path another_tablets_copy(const fs::path& file, const std::string& name) {
  return bench::another_tablets_copy(folder(), file, name);
}

void sync_bench(benchmark::State& state, const fs::path& original, int visits) {
  office::SyncResult last;
  for (auto _ : state) {
    state.PauseTiming();
    const std::string db = fresh_database();
    const fs::path copy = folder() / "synced.rockface";
    fs::remove(copy);
    fs::copy_file(original, copy);
    state.ResumeTiming();
    NoProgress none;
    last = office::sync_project(copy, server().socket_conninfo("tablet_1", db), {}, none);
  }
  const double bytes = static_cast<double>(last.blob_bytes_sent + last.record_bytes_sent);
  state.counters["visits"] = visits;
  state.counters["MB_per_visit"] = bytes / 1e6 / visits;
  state.counters["photo_mesh_MB_per_visit"] =
      static_cast<double>(last.blob_bytes_sent) / 1e6 / visits;
  state.counters["record_kB_per_visit"] =
      static_cast<double>(last.record_bytes_sent) / 1e3 / visits;
  state.counters["records"] = last.records_sent;
}

void BM_SyncOneVisit24Mpx(benchmark::State& state) {
  // Two 6000 x 4000 JPEGs and a 3D image of 250,000 vertices.
  sync_bench(state, make_project("one-visit", 1, 6000, 4000, 500), 1);
}
BENCHMARK(BM_SyncOneVisit24Mpx)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_SyncThousandVisits(benchmark::State& state) {
  // 640 x 480 photographs and 2,500-vertex meshes: the records dominate.
  sync_bench(state, make_project("thousand", 1000, 640, 480, 50), 1000);
}
BENCHMARK(BM_SyncThousandVisits)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_SecondSyncNothingChanged1000(benchmark::State& state) {
  const fs::path file = make_project("thousand", 1000, 640, 480, 50);
  const std::string db = fresh_database();
  const fs::path copy = folder() / "resynced.rockface";
  fs::remove(copy);
  fs::copy_file(file, copy);
  NoProgress none;
  office::sync_project(copy, server().socket_conninfo("tablet_1", db), {}, none);
  for (auto _ : state)
    office::sync_project(copy, server().socket_conninfo("tablet_1", db), {}, none);
}
BENCHMARK(BM_SecondSyncNothingChanged1000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_OfficeDriveQuery3000(benchmark::State& state) {
  const fs::path file = make_project("thousand", 1000, 640, 480, 50);
  const std::string db = fresh_database();
  NoProgress none;
  for (int t = 1; t <= 3; ++t) {
    const fs::path copy = another_tablets_copy(file, "tablet" + std::to_string(t));
    office::sync_project(copy, server().socket_conninfo("tablet_" + std::to_string(t), db), {},
                         none);
  }
  std::size_t placed = 0;
  for (auto _ : state) {
    const auto drive = app::server_drive(server().socket_conninfo("office_bench", db), "bench");
    placed = drive.visits.size();
  }
  state.counters["visits"] = static_cast<double>(placed);
}
BENCHMARK(BM_OfficeDriveQuery3000)->Unit(benchmark::kMillisecond)->Iterations(5);

// The rock mass and support of every round of a drive (issue 46:
// firmware-app/support/support_drive.h, what the office's rounds read from
// their copy): 300 and 3,000 bench visits in one project. Each round listed
// every visit and built the tunnel again: the time grew as the square of
// the visits.
void BM_DriveRoundsRockMass(benchmark::State& state) {
  const int visits = static_cast<int>(state.range(0));
  const fs::path file = make_project("rounds-" + std::to_string(visits), visits, 64, 48, 10);
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(file, read);
  std::size_t rounds = 0;
  for (auto _ : state) rounds = app::drive_support(store).size();
  state.counters["rounds"] = static_cast<double>(rounds);
}
BENCHMARK(BM_DriveRoundsRockMass)
    ->Arg(300)
    ->Arg(3000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
