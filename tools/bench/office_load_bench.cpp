// The office in a browser (issue 46), on loopback, bounded in count and
// time: `rockface office serve` (a child process) on a real PostgreSQL
// server (tests/support/postgres_server.h, Unix socket with trust: the
// log-ins' passwords are not checked here, fsync off) holding 3,000 visits
// of three tablets (1,000 synthetic visits each, synced as a tablet syncs).
//  - the server's start to listening, on that database;
//  - 50 client threads, each logged in, reading the drive of 3,000 visits
//    for a fixed time while a fourth tablet syncs: errors, p50 / p95, the
//    server's peak memory;
//  - the drive's first paint in headless Chromium (3,000 rows drawn);
//  - a visit with a 250,000-vertex 3D image: the decimated face's bytes and
//    time, the full mesh's, and the field report's generation on demand.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "core/common/progress.h"
#include "core/tunnel/design_profile.h"
#include "storage/office/pg_connection.h"
#include "storage/office/pull_project.h"
#include "storage/office/server_schema.h"
#include "storage/office/sqlite_rows.h"
#include "storage/office/sync_push.h"
#include "storage/project/project_store.h"
#include "tests/support/postgres_server.h"
#include "tests/support/sample_records.h"
#include "tests/support/web_driver.h"
#include "tools/bench/bench_tablet_projects.h"

#include <httplib.h>

namespace {

namespace fs = std::filesystem;
using namespace rockface;
namespace office = storage::office;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

test::PostgresServer& server() {
  static test::PostgresServer& s = []() -> test::PostgresServer& {
    static test::PostgresServer started;
    // One connection per logged-in person: 50 clients, a syncing tablet and
    // the benchmark's own need more than the test server's 40 (Debian's
    // default is 100).
    started.psql("ALTER SYSTEM SET max_connections = 100", "postgres");
    started.stop();
    started.start();
    return started;
  }();
  return s;
}

// This run's folder in the system's temporary folder (the tablets'
// projects, the servers' work folders and logs: ~2.5 GB a run), removed
// when the run ends (main).
fs::path folder_path() {
  return fs::temp_directory_path() / ("rockface-office-load-" + std::to_string(::getpid()));
}

fs::path folder() {
  static const fs::path dir = [] {
    fs::create_directories(folder_path());
    return folder_path();
  }();
  return dir;
}

std::string fresh_database(const std::string& tunnel) {
  static int n = 0;
  const std::string db = "load" + std::to_string(++n);
  server().psql("CREATE DATABASE " + db, "postgres");
  office::Connection c(server().socket_conninfo(test::PostgresServer::kSuperuser, db));
  office::init_server(c);
  office::add_tunnel(c, tunnel);
  for (const char* t : {"tablet_1", "tablet_2", "tablet_3", "tablet_4"})
    office::add_tablet(c, t, tunnel);
  office::add_office_user(c, "office_bench");
  // The web server's service role, its pooled connections' (socket: trust).
  office::add_web_service(c, "office_web_bench");
  return db;
}

// A rough face on a grid of side x side vertices, textured.
storage::Model grid_model(storage::RecordId capture, int side) {
  storage::Model m;
  m.capture_id = capture;
  m.texture_capture_id = capture;
  m.texture_side = "left";
  m.preset = "standard";
  std::mt19937 rng(7);
  std::normal_distribution<double> rough(0, 0.02);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      m.mesh.vertices.push_back({4.0 * i / side, 0.3 + rough(rng), 4.0 * j / side});
      m.mesh.texcoords.push_back({static_cast<float>(i) / side, static_cast<float>(j) / side});
    }
  for (int i = 0; i + 1 < side; ++i)
    for (int j = 0; j + 1 < side; ++j) {
      const int a = i * side + j;
      m.mesh.faces.push_back({a, a + side, a + 1});
      m.mesh.faces.push_back({a + 1, a + side, a + side + 1});
    }
  m.registration.kind = "none";
  return m;
}

// The tablets' projects (tools/bench/bench_tablet_projects.h) in this
// benchmark's folder, with its 3D image.
fs::path make_project(const std::string& name, int visits, int width, int height, int mesh_side) {
  return bench::make_bench_project(folder(), name, visits, width, height, mesh_side, grid_model);
}

fs::path another_tablets_copy(const fs::path& file, const std::string& name) {
  return bench::another_tablets_copy(folder(), file, name);
}

// The 3,000-visit database, made once.
const std::string& big_database() {
  static const std::string db = [] {
    const std::string name = fresh_database("bench");
    const fs::path file = make_project("thousand", 1000, 640, 480, 50);
    NoProgress none;
    for (int t = 1; t <= 3; ++t)
      office::sync_project(another_tablets_copy(file, "tablet" + std::to_string(t)),
                           server().socket_conninfo("tablet_" + std::to_string(t), name), {}, none);
    return name;
  }();
  return db;
}

// `rockface office serve` as a child process; the time to its listening.
struct Served {
  pid_t pid = -1;
  int port = 0;
  double start_s = 0;
  // `binary`: another build's rockface to serve (e.g. main's, for a
  // before / after on the same database); "" is this build's.
  explicit Served(const std::string& db, const std::string& other_binary = "") {
    const std::string conninfo = "host=" + server().folder().string() +
                                 " port=" + std::to_string(server().port()) + " dbname=" + db +
                                 " user=office_web_bench";
    // A log of its own: an earlier server's line must not be read as this one's.
    static int count = 0;
    const fs::path log = folder() / ("serve-" + std::to_string(++count) + ".out");
    // ROCKFACE_OFFICE_BENCH_BINARY=FILE serves every benchmark with another
    // build's rockface (a before / after of the same benchmark).
    const char* named = std::getenv("ROCKFACE_OFFICE_BENCH_BINARY");
    const std::string binary = !other_binary.empty() ? other_binary
                               : named               ? std::string(named)
                                       : std::string(ROCKFACE_BINARY_DIR) + "/rockface";
    const auto t0 = Clock::now();
    pid = ::fork();
    if (pid == 0) {
      if (!std::freopen(log.c_str(), "w", stdout)) ::_exit(126);
      // The server's failures (stderr) beside its listening line.
      ::dup2(::fileno(stdout), 2);
      // ROCKFACE_OFFICE_BENCH_POOL=N serves with N database connections
      // (`--pool`; the server's default otherwise): whether a load's
      // refusals are its pool's.
      const char* pool = std::getenv("ROCKFACE_OFFICE_BENCH_POOL");
      if (pool)
        ::execl(binary.c_str(), binary.c_str(), "office", "serve", conninfo.c_str(), "--listen",
                "127.0.0.1:0", "--work", folder().c_str(), "--pool", pool,
                static_cast<char*>(nullptr));
      else
        ::execl(binary.c_str(), binary.c_str(), "office", "serve", conninfo.c_str(), "--listen",
                "127.0.0.1:0", "--work", folder().c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    while (port == 0 && Clock::now() - t0 < std::chrono::seconds(30)) {
      std::ifstream in(log);
      std::string line;
      std::getline(in, line);
      const auto at = line.find("127.0.0.1:");
      if (at != std::string::npos && line.find('/', at) != std::string::npos)
        port = std::stoi(line.substr(at + 10));
      else
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    start_s = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  ~Served() {
    ::kill(pid, SIGTERM);
    int status = 0;
    ::waitpid(pid, &status, 0);
  }
  std::string origin() const { return "http://127.0.0.1:" + std::to_string(port); }
  double peak_rss_mb() const {
    std::ifstream in("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(in, line))
      if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return 0;
  }
};

// What a refused request was told: "STATUS message" (the server's error
// text), or how the connection failed.
std::string refusal(const httplib::Result& r) {
  if (!r) return "no answer: " + httplib::to_string(r.error());
  std::string message = r->body;
  try {
    message = json::parse(r->body).value("error", r->body);
  } catch (const json::exception&) {
  }
  return std::to_string(r->status) + " " + message;
}

std::string log_in(httplib::Client& c, const std::string& origin, std::string* refused = nullptr) {
  const auto r =
      c.Post("/api/login", {{"Origin", origin}},
             json{{"role", "office_bench"}, {"password", "trust"}}.dump(), "application/json");
  if (!r || r->status != 200) {
    if (refused) *refused = refusal(r);
    return "";
  }
  const std::string set = r->get_header_value("Set-Cookie");
  return set.substr(0, set.find(';'));
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

void BM_OfficeServeStart3000(benchmark::State& state) {
  const std::string& db = big_database();
  double start = 0;
  for (auto _ : state) {
    Served s(db);
    start = s.start_s;
  }
  state.counters["start_s"] = start;
}
BENCHMARK(BM_OfficeServeStart3000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Office50ClientsDrive3000WhileATabletSyncs(benchmark::State& state) {
  const std::string& db = big_database();
  const fs::path small = make_project("small", 20, 640, 480, 50);
  std::vector<double> latencies, visit_latencies;
  std::atomic<int> errors{0}, requests{0}, login_errors{0};
  // The refusals by what they said (shown as the benchmark's label).
  std::map<std::string, int> refusals;
  double rss = 0;
  for (auto _ : state) {
    Served s(db);
    std::mutex lock;
    std::atomic<bool> stop{false};
    std::thread tablet([&] {
      NoProgress none;
      const fs::path copy = another_tablets_copy(small, "tablet4");
      office::sync_project(copy, server().socket_conninfo("tablet_4", db), {}, none);
    });
    std::vector<std::thread> clients;
    for (int i = 0; i < 50; ++i)
      clients.emplace_back([&, i] {
        httplib::Client c("127.0.0.1", s.port);
        c.set_read_timeout(std::chrono::seconds(120));
        std::string refused;
        const std::string cookie = log_in(c, s.origin(), &refused);
        auto count_refusal = [&](const std::string& what, const std::string& why) {
          std::lock_guard guard(lock);
          ++refusals[what + ": " + why];
        };
        if (cookie.empty()) {
          ++errors;
          ++login_errors;
          count_refusal("log-in", refused);
          return;
        }
        // Each client reads the drive, then opens one of its visits at
        // random (the issue's load: "reading the drive ... and opening
        // visits at random"), over and over.
        std::mt19937 pick(static_cast<unsigned>(i + 1));
        std::vector<std::string> ids;
        std::vector<double> mine, my_visits;
        while (!stop) {
          auto t0 = Clock::now();
          const auto r = c.Get("/api/drive?tunnel=bench", {{"Cookie", cookie}});
          mine.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
          ++requests;
          if (!r || r->status != 200) {
            ++errors;
            count_refusal("drive", refusal(r));
            continue;
          }
          if (ids.empty()) {
            const json drive = json::parse(r->body);
            for (const auto& v : drive["visits"]) ids.push_back(v["id"]);
          }
          if (ids.empty() || stop) continue;
          const std::string& visit = ids[pick() % ids.size()];
          t0 = Clock::now();
          const auto v = c.Get("/api/visit?tunnel=bench&visit=" + visit, {{"Cookie", cookie}});
          my_visits.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
          ++requests;
          if (!v || v->status != 200) {
            ++errors;
            count_refusal("visit", refusal(v));
          }
        }
        std::lock_guard guard(lock);
        latencies.insert(latencies.end(), mine.begin(), mine.end());
        visit_latencies.insert(visit_latencies.end(), my_visits.begin(), my_visits.end());
      });
    // Bounded: 60 s of load, then every client finishes its request.
    std::this_thread::sleep_for(std::chrono::seconds(60));
    stop = true;
    for (auto& t : clients) t.join();
    tablet.join();
    rss = s.peak_rss_mb();
  }
  state.counters["requests"] = requests.load();
  state.counters["errors"] = errors.load();
  state.counters["login_errors"] = login_errors.load();
  state.counters["p50_ms"] = percentile(latencies, 0.5);
  state.counters["p95_ms"] = percentile(latencies, 0.95);
  state.counters["visits_opened"] = static_cast<double>(visit_latencies.size());
  state.counters["visit_p50_ms"] = percentile(visit_latencies, 0.5);
  state.counters["visit_p95_ms"] = percentile(visit_latencies, 0.95);
  state.counters["server_peak_RSS_MB"] = rss;
  std::string label;
  for (const auto& [what, n] : refusals) label += std::to_string(n) + "x " + what + "; ";
  if (!label.empty()) state.SetLabel(label);
}
BENCHMARK(BM_Office50ClientsDrive3000WhileATabletSyncs)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// The rounds along the drive of 3,000 visits (issue 46: the rounds pulled
// the whole tunnel with its photographs, then measured 3,000 meshes on
// every server's first request; then a fresh server took 284 s with every
// round kept, 552 s with none). On a database with no kept figures: the
// first request's answer (its time, and how many rounds it says are still
// being measured), the time until every round is in (asked again once a
// second, as the page polls every 3 s) and how many rounds the server
// measured, the bytes of the server's pulled copies, a request once all
// are in; then a fresh server on the same database (every round kept):
// its first answer and the time until all are in; the server's peak
// memory. A build that answers only when every round is in (main before
// this change) shows its whole time as the first answer.
// With `binary_variable` set, the rockface named by that environment
// variable serves instead of this build's.
struct RoundsRun {
  double first_s = 0, all_in_s = 0;
  int rounds = 0, first_measuring = 0, measured = 0, requests = 0;
  double page_kb = 0;
  bool ok = false;
};

RoundsRun rounds_until_all_in(httplib::Client& c, const std::string& cookie) {
  RoundsRun run;
  const auto t0 = Clock::now();
  auto ask = [&] { return c.Get("/api/drive/rounds?tunnel=bench", {{"Cookie", cookie}}); };
  auto r = ask();
  run.first_s = std::chrono::duration<double>(Clock::now() - t0).count();
  if (!r || r->status != 200) return run;
  run.rounds = static_cast<int>(json::parse(r->body)["rounds"].size());
  run.first_measuring = std::stoi("0" + r->get_header_value("X-Rockface-Rounds-Measuring"));
  int measuring = run.first_measuring;
  run.requests = 1;
  // Bounded: 30 minutes, then the run says what it had.
  while (measuring > 0 && Clock::now() - t0 < std::chrono::minutes(30)) {
    std::this_thread::sleep_for(std::chrono::seconds(1));
    r = ask();
    ++run.requests;
    if (!r || r->status != 200) return run;
    measuring = std::stoi("0" + r->get_header_value("X-Rockface-Rounds-Measuring"));
  }
  run.all_in_s = std::chrono::duration<double>(Clock::now() - t0).count();
  run.measured = std::stoi("0" + r->get_header_value("X-Rockface-Rounds-Measured"));
  run.page_kb = static_cast<double>(r->body.size()) / 1024;
  run.ok = measuring == 0;
  return run;
}

void BM_OfficeRounds3000(benchmark::State& state, const char* binary_variable) {
  std::string binary;
  if (*binary_variable) {
    const char* named = std::getenv(binary_variable);
    if (!named) {
      state.SkipWithError(
          (std::string("set ") + binary_variable + " to measure another build").c_str());
      return;
    }
    binary = named;
  }
  const std::string& db = big_database();
  // No kept figures: every round measured by this run's first server.
  server().psql("DELETE FROM rockface.round_figures", db);
  RoundsRun first, fresh;
  double again_s = 0, copy_mb = 0, rss = 0;
  for (auto _ : state) {
    Served s(db, binary);
    httplib::Client c("127.0.0.1", s.port);
    c.set_read_timeout(std::chrono::seconds(1800));
    const std::string cookie = log_in(c, s.origin());
    first = rounds_until_all_in(c, cookie);
    if (!first.ok) {
      state.SkipWithError("the rounds were not all served");
      return;
    }
    const auto t0 = Clock::now();
    c.Get("/api/drive/rounds?tunnel=bench", {{"Cookie", cookie}});
    again_s = std::chrono::duration<double>(Clock::now() - t0).count();
    std::uintmax_t bytes = 0;
    const fs::path shared = folder() / ("rockface-office-" + std::to_string(s.pid)) / "shared";
    for (const auto& e : fs::directory_iterator(shared))
      if (e.path().extension() == ".rockface") bytes += fs::file_size(e.path());
    copy_mb = static_cast<double>(bytes) / (1024 * 1024);
    rss = s.peak_rss_mb();
    // A server started afresh on the same database: the figures kept by the
    // first.
    Served again(db, binary);
    httplib::Client f("127.0.0.1", again.port);
    f.set_read_timeout(std::chrono::seconds(1800));
    fresh = rounds_until_all_in(f, log_in(f, again.origin()));
  }
  state.counters["rounds"] = first.rounds;
  state.counters["first_answer_s"] = first.first_s;
  state.counters["first_answer_measuring"] = first.first_measuring;
  state.counters["all_in_s"] = first.all_in_s;
  state.counters["measured"] = first.measured;
  state.counters["polls"] = first.requests;
  state.counters["again_s"] = again_s;
  state.counters["fresh_first_answer_s"] = fresh.first_s;
  state.counters["fresh_all_in_s"] = fresh.all_in_s;
  state.counters["fresh_measured"] = fresh.measured;
  state.counters["pulled_copy_MB"] = copy_mb;
  state.counters["page_kB"] = first.page_kb;
  state.counters["server_peak_RSS_MB"] = rss;
}
BENCHMARK_CAPTURE(BM_OfficeRounds3000, other_build, "ROCKFACE_OTHER_BINARY")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_OfficeRounds3000, this_build, "")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// Opening one visit of the 3,000-visit drive (issue 46: the visit page
// pulled the whole tunnel with its photographs): the visit page's first
// request, the bytes the server pulled for it, then one photograph shown;
// beside it the pull the page made before (the whole tunnel with its
// photographs, pull_tunnel as `rockface pull` runs it: a build from
// before schema 3 cannot serve this database).
void BM_OfficeVisitOpen3000(benchmark::State& state) {
  const std::string& db = big_database();
  double open_s = 0, photo_s = 0, copy_mb = 0, photo_kb = 0, whole_s = 0, whole_mb = 0;
  for (auto _ : state) {
    Served s(db);
    httplib::Client c("127.0.0.1", s.port);
    c.set_read_timeout(std::chrono::seconds(1800));
    const std::string cookie = log_in(c, s.origin());
    const auto d = c.Get("/api/drive?tunnel=bench", {{"Cookie", cookie}});
    if (!d || d->status != 200) {
      state.SkipWithError("the drive was not served");
      return;
    }
    const json visits = json::parse(d->body)["visits"];
    // A visit in the drive's middle.
    const std::string visit = visits[visits.size() / 2]["id"];
    auto t0 = Clock::now();
    const auto v = c.Get("/api/visit?tunnel=bench&visit=" + visit, {{"Cookie", cookie}});
    open_s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (!v || v->status != 200) {
      state.SkipWithError("the visit was not served");
      return;
    }
    const json photo = json::parse(v->body)["photos"][0];
    t0 = Clock::now();
    const auto p = c.Get("/api/visit/photo?tunnel=bench&visit=" + visit +
                             "&capture=" + std::to_string(photo["capture"].get<std::int64_t>()) +
                             "&side=" + photo["side"].get<std::string>(),
                         {{"Cookie", cookie}});
    photo_s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (p && p->status == 200) photo_kb = static_cast<double>(p->body.size()) / 1024;
    std::uintmax_t bytes = 0;
    const fs::path shared = folder() / ("rockface-office-" + std::to_string(s.pid)) / "shared";
    for (const auto& e : fs::directory_iterator(shared))
      if (e.path().extension() == ".rockface") bytes += fs::file_size(e.path());
    copy_mb = static_cast<double>(bytes) / (1024 * 1024);

    const fs::path whole = folder() / "whole-tunnel.rockface";
    fs::remove(whole);
    NoProgress none;
    t0 = Clock::now();
    office::pull_tunnel(server().socket_conninfo("office_bench", db), "bench", whole, none);
    whole_s = std::chrono::duration<double>(Clock::now() - t0).count();
    whole_mb = static_cast<double>(fs::file_size(whole)) / (1024 * 1024);
    fs::remove(whole);
  }
  state.counters["open_s"] = open_s;
  state.counters["pulled_copy_MB"] = copy_mb;
  state.counters["photo_s"] = photo_s;
  state.counters["photo_kB"] = photo_kb;
  state.counters["whole_pull_s"] = whole_s;
  state.counters["whole_pull_MB"] = whole_mb;
}
BENCHMARK(BM_OfficeVisitOpen3000)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_DriveFirstPaint3000(benchmark::State& state) {
  if (!office_web_test::WebDriver::available()) {
    state.SkipWithError("chromium is not installed");
    return;
  }
  const std::string& db = big_database();
  Served s(db);
  double paint = 0, rounds_paint = 0, rounds_in = 0;
  int rows = 0;
  for (auto _ : state) {
    office_web_test::WebDriver d(1280, 900);
    d.go(s.origin() + "/");
    d.type(d.wait_for("#role"), "office_bench");
    d.type(d.wait_for("#password"), "trust");
    d.click(d.wait_for("#login button[type=submit]"));
    d.wait_for("a.tunnel-link");
    const auto t0 = Clock::now();
    d.click(d.wait_for("a.tunnel-link"));
    d.wait_for("table.visits tbody tr", std::chrono::seconds(120));
    paint = std::chrono::duration<double>(Clock::now() - t0).count();
    rows = d.script("return document.querySelectorAll('table.visits tbody tr').length").get<int>();
    // The rounds' table, answered at once (issue 46), then filled in.
    d.wait_for("table.rounds tbody tr", std::chrono::seconds(600));
    rounds_paint = std::chrono::duration<double>(Clock::now() - t0).count();
    d.wait_for("#rounds-status.rounds-done", std::chrono::seconds(1800));
    rounds_in = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  state.counters["first_paint_s"] = paint;
  state.counters["rows"] = rows;
  state.counters["rounds_paint_s"] = rounds_paint;
  state.counters["rounds_all_in_s"] = rounds_in;
}
BENCHMARK(BM_DriveFirstPaint3000)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_FaceTransferAndReport(benchmark::State& state) {
  // One visit with two 24 Mpx photographs and a 250,000-vertex 3D image.
  const std::string db = fresh_database("bench");
  NoProgress none;
  office::sync_project(make_project("one-visit", 1, 6000, 4000, 500),
                       server().socket_conninfo("tablet_1", db), {}, none);
  Served s(db);
  httplib::Client c("127.0.0.1", s.port);
  c.set_read_timeout(std::chrono::seconds(300));
  const std::string cookie = log_in(c, s.origin());
  const auto drive = c.Get("/api/drive?tunnel=bench", {{"Cookie", cookie}});
  const std::string visit = json::parse(drive->body)["visits"][0]["id"];
  const std::string q = "?tunnel=bench&visit=" + visit;
  auto timed = [&](const std::string& path, double& seconds, const std::string& more = "") {
    const auto t0 = Clock::now();
    const auto r = c.Get((path + q + more).c_str(), {{"Cookie", cookie}});
    seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r && r->status == 200 ? r->body.size() : 0;
  };
  double first_open = 0, decimated_s = 0, full_s = 0, report_s = 0;
  std::size_t decimated = 0, full = 0, pdf = 0;
  for (auto _ : state) {
    timed("/api/visit", first_open);  // pulls the tunnel for the session
    decimated = timed("/api/visit/mesh", decimated_s);
    full = timed("/api/visit/mesh", full_s, "&full=1");
    pdf = timed("/api/visit/report.pdf", report_s);
  }
  state.counters["visit_first_open_s"] = first_open;
  state.counters["face_kB"] = static_cast<double>(decimated) / 1024;
  state.counters["face_s"] = decimated_s;
  state.counters["full_face_kB"] = static_cast<double>(full) / 1024;
  state.counters["full_face_s"] = full_s;
  state.counters["report_s"] = report_s;
  state.counters["report_kB"] = static_cast<double>(pdf) / 1024;
}
BENCHMARK(BM_FaceTransferAndReport)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  // Every server is stopped by now (each benchmark's own); the PostgreSQL
  // server's folder goes with its static object at exit.
  std::error_code ec;
  fs::remove_all(folder_path(), ec);
  return 0;
}
