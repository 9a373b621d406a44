// A whole visit at the face's pace (issue 45): one, two and three 24 Mpx
// stereo pairs of the synthetic tunnel face from the camera to the merged
// face's block table, stage by stage, per preset, with the child's CPU time
// and peak memory.
//
// The visit: tools/samples/tunnel-face.scene.json (6000 x 4000 px, range
// pole and compass line, three joints, the render's true traces: the scene
// has no picks) photographed from its own pair of stations (the middle
// pair, registered by pole and compass) and, for two and three pairs, from
// a pair 1.1 m to the West looking at the face's western corner and one
// 1.1 m to the East looking at its eastern corner (each further pair is
// registered to the face: SIFT tie points, similarity, ICP).
//
// `rockface replay` runs as a child process (tools/bench/replay_child.h);
// its progress lines are timed on arrival with the child's CPU time and peak
// resident set. Stages (pair k's lines are "pair k: ..."):
//   capture_k  the mock camera rendering pair k (it stands in for the
//              camera and is taken out of every figure below)
//   pair_k     pair k's reconstruction (features, orientation, dense) and,
//              for pair 1, its registration by pole and compass and saving
//   merge      the further pairs registered to pair 1, their models saved
//   analysis   the trace records, pyramids, trace map, blocks, rotation,
//              limit equilibrium, the analysis saved
// Counters (seconds; CPU is the child's, every thread):
//   processing_s / processing_cpu_s  everything but the captures: what the
//              visit costs the tablet
//   wait_s     the wait after the last shot: the last pair's download (its
//              two JPEGs as stored, at kDownloadMBps, a 24 Mpx DSLR's JPEG
//              over USB 2), its reconstruction, the merge and the analysis.
//              It assumes the earlier pairs were reconstructed while the next
//              ones were shot (each pair_k_s is the time that needs: compare
//              it with the minute a geologist takes to walk to the next
//              station); the replay itself runs them one after the other.
//   download_s the last pair's download at that rate
//   peak_MB    the child's peak resident set (ru_maxrss), the mock camera's
//              two rendered frames and their truth included; recon_peak_MB
//              the peak at the end of the last reconstruction
//   models, blocks  what the visit holds at the end (the accuracy side:
//              registration_rms_mm is the worst further pair's surface
//              residual on pair 1 after ICP)
//
// Usage: tools/bench/run.sh visit_bench [--benchmark_filter=visit/3/standard]
// (a three-pair visit at precise renders six 24 Mpx photographs and peaks
// near 2 GB: run one preset at a time on a small machine).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"
#include "tools/bench/replay_child.h"

namespace fs = std::filesystem;
using rockface::bench::ReplayRun;
using rockface::bench::StageMark;

namespace {

// A 24 Mpx DSLR's JPEG over USB 2 (PTP): ~25 MB/s in practice.
constexpr double kDownloadMBps = 25.0;

const fs::path& work_dir() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("rockface-visit-bench-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// The tunnel face with `pairs` pairs of stations: the scene's own pair
// first (the one that sees the pole), then West, then East.
fs::path scene_with_pairs(int pairs) {
  const fs::path out = work_dir() / ("tunnel-face-" + std::to_string(pairs) + "-pairs.scene.json");
  if (fs::exists(out)) return out;
  std::ifstream in(std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face.scene.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  nlohmann::json& stations = scene["imaging"]["stations"];
  const nlohmann::json middle = stations;
  // The face runs East-West 6 m wide at N ~5211880.3; its corners at E
  // 512337 and 512343. A further pair moved 1.1 m along it and turned to
  // the corner overlaps the middle pair by about two thirds.
  for (int k = 1; k < pairs; ++k) {
    const double shift = k == 1 ? -1.1 : 1.1;
    const double look_e = k == 1 ? 512338.0 : 512342.0;
    for (nlohmann::json s : middle) {
      s["position"][0] = s["position"][0].get<double>() + shift;
      s["look_at"][0] = look_e;
      stations.push_back(s);
    }
  }
  std::ofstream(out) << scene.dump(2);
  return out;
}

// The pair a progress line belongs to (1 when unprefixed) and the line
// without its prefix.
std::pair<int, std::string> pair_of(const std::string& line) {
  if (line.rfind("pair ", 0) == 0) {
    const auto colon = line.find(": ");
    if (colon != std::string::npos) return {std::stoi(line.substr(5)), line.substr(colon + 2)};
  }
  return {1, line};
}

// The stage a line opens, given the current one ("" keeps the current).
std::string stage_of(const std::string& line, const std::string& current) {
  const auto [pair, rest] = pair_of(line);
  if (rest == "capture") return "capture_" + std::to_string(pair);
  if (current.rfind("capture_", 0) == 0) return "pair_" + current.substr(8);
  if (rest.rfind("registering", 0) == 0) return "merge";
  if (rest == "measure" || rest == "blocks") return "analysis";
  return "";
}

struct StageFigures {
  double wall_s = 0, cpu_s = 0, end_mb = 0;
};

std::map<std::string, StageFigures> stages(const ReplayRun& run) {
  std::map<std::string, StageFigures> out;
  std::string stage = "capture_1";
  double wall0 = 0, cpu0 = 0;
  auto close = [&](double wall, double cpu, double mb) {
    auto& f = out[stage];
    f.wall_s += wall - wall0;
    f.cpu_s += cpu - cpu0;
    f.end_mb = mb;
    wall0 = wall;
    cpu0 = cpu;
  };
  for (const StageMark& m : run.marks) {
    const std::string s = stage_of(m.stage, stage);
    if (s.empty() || s == stage) continue;
    close(m.at_s, m.cpu_s, m.hwm_mb);
    stage = s;
  }
  close(run.total_s, run.cpu_s, run.peak_mb);
  return out;
}

void visit(benchmark::State& state, int pairs, const std::string& preset) {
  const fs::path scene = scene_with_pairs(pairs);
  const fs::path project = work_dir() / ("visit-" + std::to_string(pairs) + "-" + preset + ".rf");
  ReplayRun run;
  for (auto _ : state) {
    fs::remove(project);
    run = rockface::bench::run_replay(std::string(ROCKFACE_BINARY_DIR) + "/rockface",
                                      scene.string(), project.string(), preset);
    if (!run.ok()) {
      const std::string why = "rockface replay failed (run it by hand on " + scene.string() + ")";
      state.SkipWithError(why.c_str());
      return;
    }
  }
  const auto figures = stages(run);
  double capture_s = 0, capture_cpu_s = 0, recon_peak = 0;
  for (const auto& [name, f] : figures) {
    state.counters[name + "_s"] = f.wall_s;
    state.counters[name + "_cpu_s"] = f.cpu_s;
    if (name.rfind("capture_", 0) == 0) {
      capture_s += f.wall_s;
      capture_cpu_s += f.cpu_s;
    }
    if (name == "pair_" + std::to_string(pairs)) recon_peak = f.end_mb;
  }
  state.counters["processing_s"] = run.total_s - capture_s;
  state.counters["processing_cpu_s"] = run.cpu_s - capture_cpu_s;
  state.counters["peak_MB"] = run.peak_mb;
  state.counters["recon_peak_MB"] = recon_peak;

  namespace rs = rockface::storage;
  rs::OpenOptions open;
  open.read_only = true;
  rs::ProjectStore store = rs::ProjectStore::open(project, open);
  const auto captures = store.list_captures();
  const double last_pair_mb =
      captures.empty()
          ? 0
          : static_cast<double>(captures.back().left_bytes + captures.back().right_bytes) / 1e6;
  const double download_s = last_pair_mb / kDownloadMBps;
  auto at = [&](const std::string& k) {
    const auto it = figures.find(k);
    return it == figures.end() ? 0.0 : it->second.wall_s;
  };
  state.counters["download_s"] = download_s;
  state.counters["wait_s"] =
      download_s + at("pair_" + std::to_string(pairs)) + at("merge") + at("analysis");
  double worst_rms = 0;
  const auto models = store.list_models();
  for (const auto& m : models)
    if (m.registration_kind == "face_images") worst_rms = std::max(worst_rms, m.registration_rms_m);
  state.counters["models"] = static_cast<double>(models.size());
  state.counters["registration_rms_mm"] = worst_rms * 1000;
  const auto analyses = store.list_analyses();
  if (!analyses.empty())
    state.counters["blocks"] =
        static_cast<double>(store.load_analysis(analyses.back().id).blocks.size());
  fs::remove(project);
}

}  // namespace

int main(int argc, char** argv) {
  for (const char* preset : {"fast", "standard", "precise"})
    for (int pairs : {1, 2, 3})
      benchmark::RegisterBenchmark(
          ("visit/" + std::to_string(pairs) + "/" + preset).c_str(),
          [preset, pairs](benchmark::State& state) { visit(state, pairs, preset); })
          ->Iterations(1)
          ->Unit(benchmark::kSecond)
          ->UseRealTime();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  fs::remove_all(work_dir());
  return 0;
}
