// The Mapping screen's blocks after an edit (issue 28): a face mapped trace
// by trace (tests/support/dense_face.h: a 20 x 10 m face, each trace with a
// joint plane of its own) stored in a project; each iteration stores one
// more trace, as "Save trace" does, and times what the tablet's worker does
// next: StoreTraceMapRunner::update — read the visit from the project, the
// scene, and faces::TraceSession's update, which recomputes only the regions
// the new trace touched. On one core (ROCKFACE_THREADS=1), the tablet's
// worker beside its UI thread.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/common/progress.h"
#include "core/common/units.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "tests/support/dense_face_visit.h"
#include "tests/support/random_slope.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;

// A visit of `areas` (the surface), `joints` and the first n of `traces`;
// each iteration stores the next trace and times the update.
void edits_to_verdicts(benchmark::State& state, const std::vector<storage::Measurement>& areas,
                       const std::vector<storage::Joint>& joints,
                       const std::vector<storage::Measurement>& traces, int n) {
  ::setenv("ROCKFACE_THREADS", "1", 1);
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-map-bench-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "face.rockface";
  storage::ProjectInfo info;
  info.name = "face mapped trace by trace";
  info.datum = {2690000.0, 1170000.0, 1100.0};
  storage::RecordId visit = 0;
  {
    storage::ProjectStore store = storage::ProjectStore::create(file, info);
    visit = store.begin_visit("tablet");
    std::vector<storage::Measurement> measurements = areas;
    measurements.insert(measurements.end(), traces.begin(), traces.begin() + n);
    store.save_measurements(visit, measurements);
    store.save_joints(visit, {}, joints);
  }
  NoProgress progress;
  app::StoreTraceMapRunner runner;
  const ui::MapVerdicts first = runner.update(file, visit, progress);  // the screen opening
  int next = n;
  double session_ms = 0, recomputed = 0, blocks = 0;
  for (auto _ : state) {
    state.PauseTiming();
    {
      storage::ProjectStore store = storage::ProjectStore::open(file);
      store.save_measurements(visit, {traces.at(next++)});
    }
    state.ResumeTiming();
    const ui::MapVerdicts v = runner.update(file, visit, progress);
    session_ms += v.milliseconds;
    recomputed += v.recomputed;
    blocks = static_cast<double>(v.blocks.size());
  }
  const double edits = static_cast<double>(state.iterations());
  state.counters["regions"] = first.recomputed;
  state.counters["blocks"] = blocks;
  state.counters["recomputed"] = recomputed / edits;
  state.counters["session_ms"] = session_ms / edits;
  fs::remove_all(dir);
}
constexpr int kEdits = 40;

// The benched slope of faces_bench (tests/support/random_slope.h): five
// patches 40 m along strike, traces of three joint sets, 2-8 m long: the
// 1000-trace map of issue 17's BM_TraceEditToVerdicts, as a stored visit.
void BM_SlopeEditToVerdicts(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto patches = faces::testing::random_slope();
  const faces::FreeSurface surface = faces::FreeSurface::build(patches, faces::testing::kSnap);
  std::vector<storage::Measurement> areas, traces;
  for (const auto& p : patches) {
    storage::Measurement area;
    area.kind = storage::Measurement::Kind::area;
    area.label = p.id;
    area.points = p.polygon;
    areas.push_back(area);
  }
  std::vector<storage::Joint> joints;
  for (int k = 0; k < 3; ++k) {
    const faces::TraceJoint tj = faces::testing::joint_set(k);
    storage::Joint j;
    j.label = tj.id;
    j.dip_deg = rad_to_deg(tj.orientation.dip);
    j.dipdir_deg = rad_to_deg(tj.orientation.dipdir);
    j.friction_deg = rad_to_deg(*tj.friction);
    j.cohesion_pa = 0;
    j.source = "set";
    j.type = "set";
    joints.push_back(j);
  }
  for (const auto& t : faces::testing::random_traces(surface, n + kEdits, 11)) {
    storage::Measurement m;
    m.kind = storage::Measurement::Kind::trace;
    m.label = t.id;
    m.joint_label = t.joint->id;
    m.points = t.points;
    traces.push_back(m);
  }
  edits_to_verdicts(state, areas, joints, traces, n);
}
BENCHMARK(BM_SlopeEditToVerdicts)
    ->Arg(200)
    ->Arg(1000)
    ->Iterations(kEdits)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// A 20 x 10 m tunnel face mapped trace by trace, each trace with a joint
// plane of its own (tests/support/dense_face.h): far denser than the slope.
void BM_DenseFaceEditToVerdicts(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const test::DenseFace face = test::dense_face(n + kEdits);
  std::vector<storage::Joint> joints;
  std::vector<storage::Measurement> traces;
  for (const auto& t : face.traces) {
    joints.push_back(test::joint_of(t));
    traces.push_back(test::trace_measurement(t));
  }
  edits_to_verdicts(state, {test::face_area(face)}, joints, traces, n);
}
BENCHMARK(BM_DenseFaceEditToVerdicts)
    ->Arg(200)
    ->Arg(1000)
    ->Iterations(kEdits)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
