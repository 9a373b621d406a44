// Trace proposals (issue 25): time, peak memory, precision and recall per
// preset, on the rendered faces of tests/integration/proposals (the dense
// face, 12 + 2 joints) at 1200 x 800 and at 6000 x 4000 (24 Mpx, the DSLR's
// frame), each reconstructed once with the fast preset. Precision and
// recall are against the true traces within 5 cm.
//
// The dark-trace faces of issue 38 (tests/support/dark_trace_faces.h:
// sparse, medium and dense networks of dark traces without relief crossing
// each other, the demo camera at 1500 x 1000), each reconstructed at the
// preset it is proposed at, as the tablet does (BM_DarkTraceProposals):
// time of the proposals and of the facets on the same model, precision
// and recall against the true traces within 5 cm.
//
// Memory: the process's peak resident set while proposing (VmHWM, reset
// before each run through /proc/self/clear_refs), and what it adds to the
// resident set before the run (the model, picker and photograph are
// already loaded, as on the tablet).
//
// Issue 45's budget (BM_FacetsAndProposals24Mpx): the dense face at 6000 x
// 4000 reconstructed at the preset it is proposed at, as the tablet's Find
// traces runs it (the cues, the first proposals, the facets, the rest
// linked to them): the CPU time of each stage (every thread's, between the
// stages' progress reports), to the first proposals and to the whole (the
// calling thread's, first_s / total_s, and every thread's, process_*: the
// cues' stripes and OpenCV's own pool take a share), the wall time to
// each (wall_*: what the geologist waits, on an idle machine), and the
// peak memory added.
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/measure/facets/facets.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "firmware-app/propose/trace_proposals_run.h"
#include "tests/support/dark_trace_faces.h"
#include "tests/support/proposal_faces.h"

namespace rm = rockface::measure;
namespace rt = rockface::testing;

namespace {

double status_mb(const char* field) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(field, 0) == 0) return std::stod(line.substr(std::string(field).size())) / 1024;
  return 0;
}

void reset_peak() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

double cpu_s(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double thread_cpu_s() {
  return cpu_s(CLOCK_THREAD_CPUTIME_ID);
}

// Every thread's: OpenCV hands some of its work (colour conversion,
// resizing) to its own pool, which the thread's clock does not see.
double process_cpu_s() {
  return cpu_s(CLOCK_PROCESS_CPUTIME_ID);
}

// Seconds on the steady clock: what the geologist waits.
double wall_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The process's CPU time (every thread's: the cues' stripes run on the
// analysis threads, issue 45) at each new stage a worker reports: the time
// of a stage is the CPU from its report to the next stage's.
class StageClock final : public rockface::Progress {
 public:
  void report(std::string_view stage, double) override {
    if (!stages_.empty() && stages_.back().first == stage) return;
    stages_.emplace_back(std::string(stage), process_cpu_s());
  }
  bool cancel_requested() const override { return false; }
  // (stage, CPU seconds) up to `end`.
  std::vector<std::pair<std::string, double>> durations(double end) const {
    std::vector<std::pair<std::string, double>> out;
    for (std::size_t i = 0; i < stages_.size(); ++i)
      out.emplace_back(stages_[i].first,
                       (i + 1 < stages_.size() ? stages_[i + 1].second : end) - stages_[i].second);
    return out;
  }

 private:
  std::vector<std::pair<std::string, double>> stages_;
};

struct Face {
  rt::ProposalFace face;
  std::unique_ptr<rm::MeshPicker> picker;
};

// A proposal face at the given frame width (height 2/3 of it).
const Face& face(int width) {
  static std::map<int, std::unique_ptr<Face>> faces;
  auto& f = faces[width];
  if (!f) {
    f = std::make_unique<Face>();
    auto scene = rt::proposal_face_scene(rt::JointDensity::dense);
    const auto base = rockface::testing::synthetic_face(width, width * 2 / 3, false, 2.0);
    scene.camera = base.camera;
    f->face = rt::build_proposal_face_from(rt::JointDensity::dense, scene, rockface::Preset::fast);
    f->picker = std::make_unique<rm::MeshPicker>(f->face.rec.mesh);
  }
  return *f;
}

void BM_TraceProposals(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  const auto preset = static_cast<rockface::Preset>(state.range(1));
  const Face& f = face(width);
  auto options = rm::proposal_options(preset);
  options.measure.point_sigma = f.face.rec.accuracy.sigma_z;
  rockface::NoProgress progress;
  rm::ProposalResult result;
  const double before = status_mb("VmRSS:");
  reset_peak();
  for (auto _ : state) {
    result = rm::propose_traces(f.face.rec.mesh, *f.picker, f.face.left, f.face.render.images[0],
                                f.face.facets, options, progress, "bench");
    benchmark::DoNotOptimize(result);
  }
  const double peak = status_mb("VmHWM:");
  const auto score = rt::score_proposals(f.face, result.proposals, *f.picker, 0.05);
  state.SetLabel(std::string(rockface::preset_name(preset)) + ", " + std::to_string(width) +
                 " px wide");
  state.counters["precision"] = score.precision;
  state.counters["recall"] = score.recall;
  state.counters["proposals"] = static_cast<double>(score.proposals);
  state.counters["work_scale"] = result.pixel_scale;
  state.counters["peak_MB"] = peak;
  state.counters["added_MB"] = peak - before;
  state.counters["mesh_points"] = static_cast<double>(f.face.rec.mesh.size());
}

void BM_DarkTraceProposals(benchmark::State& state) {
  const auto network = static_cast<rt::TraceNetwork>(state.range(0));
  const auto preset = static_cast<rockface::Preset>(state.range(1));
  const rt::ProposalFace f = rt::build_dark_trace_face(network, preset);
  const rm::MeshPicker picker(f.rec.mesh);
  auto options = rm::proposal_options(preset);
  options.measure.point_sigma = f.rec.accuracy.sigma_z;
  rockface::NoProgress progress;
  rm::ProposalResult result;
  for (auto _ : state) {
    result = rm::propose_traces(f.rec.mesh, picker, f.left, f.render.images[0], f.facets, options,
                                progress, "bench");
    benchmark::DoNotOptimize(result);
  }
  // The facets of the same model, as `rockface propose` finds them before
  // the traces: timed on their own (CPU of this thread).
  rm::MeasureSettings settings;
  settings.point_sigma = f.rec.accuracy.sigma_z;
  settings.correlation_length =
      f.rec.point_spacing * rockface::photogrammetry::reconstruction_preset(preset).sgbm_block_size;
  const auto cpu = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  const double facets_from = cpu();
  const rm::FacetSearch facets =
      rm::find_facets(f.rec.mesh, settings, rm::facet_options(preset), progress);
  state.counters["facets_s"] = cpu() - facets_from;
  state.counters["facets"] = static_cast<double>(facets.facets.size());
  const auto score = rt::score_proposals(f, result.proposals, picker, 0.05);
  state.SetLabel(std::string(rt::network_name(network)) + ", " +
                 std::string(rockface::preset_name(preset)));
  state.counters["precision"] = score.precision;
  state.counters["recall"] = score.recall;
  state.counters["proposals"] = static_cast<double>(score.proposals);
  state.counters["truth_m"] = score.truth_m;
  state.counters["mesh_points"] = static_cast<double>(f.rec.mesh.size());
}

// Facets and proposals of the dense face at 24 Mpx, reconstructed at the
// preset they are found at, as the tablet's Find traces runs them
// (propose_first_then_facets: the cues, the first proposals, the facets,
// the rest in batches): CPU to the first proposals and to the whole result.
void BM_FacetsAndProposals24Mpx(benchmark::State& state) {
  const auto preset = static_cast<rockface::Preset>(state.range(0));
  auto scene = rt::proposal_face_scene(rt::JointDensity::dense);
  scene.camera = rockface::testing::synthetic_face(6000, 4000, false, 2.0).camera;
  const rt::ProposalFace f = rt::build_proposal_face_from(rt::JointDensity::dense, scene, preset);
  const rm::MeshPicker picker(f.rec.mesh);
  rm::ProposalResult result;
  StageClock clock;
  double first_s = 0, total_s = 0, process_first_s = 0, process_total_s = 0, wall_first_s = 0,
         wall_total_s = 0;
  std::size_t first_count = 0;
  const double before = status_mb("VmRSS:");
  reset_peak();
  for (auto _ : state) {
    const double from = thread_cpu_s(), process_from = process_cpu_s(), wall_from = wall_s();
    result = rockface::app::propose_first_then_facets(
        f.rec.mesh, picker, f.left, f.render.images[0], preset, f.rec.accuracy.sigma_z, clock,
        [&, batches = 0](const std::vector<rm::TraceProposal>& batch) mutable {
          if (batches++ > 0) return;  // the first batch: what the screen shows first
          first_s = thread_cpu_s() - from;
          process_first_s = process_cpu_s() - process_from;
          wall_first_s = wall_s() - wall_from;
          first_count = batch.size();
        });
    total_s = thread_cpu_s() - from;
    process_total_s = process_cpu_s() - process_from;
    wall_total_s = wall_s() - wall_from;
    benchmark::DoNotOptimize(result);
  }
  const double peak = status_mb("VmHWM:");
  double facets_s = 0;
  for (const auto& [stage, s] : clock.durations(process_cpu_s())) {
    state.counters["s:" + stage] = s;
    if (stage.rfind("facets", 0) == 0) facets_s += s;
  }
  const auto score = rt::score_proposals(f, result.proposals, picker, 0.05);
  state.SetLabel(std::string(rockface::preset_name(preset)));
  state.counters["facets_s"] = facets_s;
  state.counters["first_s"] = first_s;
  state.counters["first_proposals"] = static_cast<double>(first_count);
  state.counters["total_s"] = total_s;
  state.counters["process_first_s"] = process_first_s;
  state.counters["process_total_s"] = process_total_s;
  state.counters["wall_first_s"] = wall_first_s;
  state.counters["wall_total_s"] = wall_total_s;
  state.counters["precision"] = score.precision;
  state.counters["recall"] = score.recall;
  state.counters["proposals"] = static_cast<double>(score.proposals);
  state.counters["mesh_points"] = static_cast<double>(f.rec.mesh.size());
  state.counters["peak_MB"] = peak;
  state.counters["added_MB"] = peak - before;
}

}  // namespace

BENCHMARK(BM_FacetsAndProposals24Mpx)
    ->Arg(static_cast<int>(rockface::Preset::fast))
    ->Arg(static_cast<int>(rockface::Preset::standard))
    ->Arg(static_cast<int>(rockface::Preset::precise))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK(BM_DarkTraceProposals)
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK(BM_TraceProposals)
    ->ArgsProduct({{1200, 6000}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK_MAIN();
