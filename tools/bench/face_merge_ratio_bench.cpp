// Five images against two (issue 28): the 2, 5 and 10-image merges of the
// synthetic face (face_merge_runs.h; stations 1 m apart for 2 and 5, 0.5 m
// for 10), interleaved so that the load of a shared machine falls on all
// of them alike, and the table docs/accuracy-cost.md quotes ("Five images
// against two (the merge)"). tools/bench/face_merge_ratio.sh builds and
// runs it.
//
// Round after round each merge runs once, in an order that turns by one
// each round. One cold run of each comes first and is not counted
// (first-call allocations, OpenCV's and TBB's thread pools; the 2-image one
// is reported as cold2_s). Per merge: the wall time's median and range over
// the rounds, the process CPU time (every thread), and where the CPU went
// (MergeTimes). Ratios to the 2-image merge: of the wall medians, each
// round's own (median and range), of the CPU medians, and the two-core
// estimate below. One line per round goes to stderr, and the table at the end.
//
// Why CPU time and the two-core estimate: on this 2-core machine shared
// with other processes the kernel gives the process about one share of CPU
// whether it runs one thread or two (sched_autogroup), so under load the
// wall ratio tends to the CPU ratio; on two free cores it is the ratio of
// the critical paths. The estimate is that critical path computed from the
// CPU each stage took: the per-image phases (preparation and SIFT,
// thumbnails, release) split over the two cores, each wave as long as its
// longest registration or half of its registrations' sum, whichever is
// longer. It is an estimate (a stage may use a core less well than that),
// not a measurement: the wall times on an idle machine are.
#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "tools/bench/face_merge_runs.h"

namespace rp = rockface::photogrammetry;
using rockface::bench::face_images;
using rockface::bench::load_average;
using rockface::bench::MergeRun;
using rockface::bench::run_merge;

namespace {

double sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

// CPU seconds of each registration (matching, RANSAC, surface stage).
std::vector<double> registration_cpu(const rp::MergeTimes& t) {
  std::vector<double> r(t.match_cpu_s.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    r[i] = t.match_cpu_s[i] + t.ransac_cpu_s[i] + t.surface_cpu_s[i];
  return r;
}

// The merge's critical path on two free cores, from the CPU of its stages
// (the file's comment).
double two_core_estimate(const rp::MergeTimes& t) {
  const std::vector<double> reg = registration_cpu(t);
  double waves = 0;
  for (std::size_t w = 0; w < t.waves_s.size(); ++w) {
    double longest = 0, total = 0;
    for (std::size_t i = 0; i < reg.size(); ++i)
      if (t.wave[i] == static_cast<int>(w)) {
        longest = std::max(longest, reg[i]);
        total += reg[i];
      }
    waves += std::max(longest, 0.5 * total);
  }
  return 0.5 * (t.features_cpu_s + t.thumbnails_cpu_s + t.release_cpu_s) + waves;
}

struct Row {
  std::string name;
  std::vector<MergeRun> runs;
  std::vector<double> column(double (*get)(const MergeRun&)) const {
    std::vector<double> v;
    for (const auto& r : runs) v.push_back(get(r));
    return v;
  }
  double med(double (*get)(const MergeRun&)) const { return median(column(get)); }
  double min(double (*get)(const MergeRun&)) const {
    const auto v = column(get);
    return *std::min_element(v.begin(), v.end());
  }
  double max(double (*get)(const MergeRun&)) const {
    const auto v = column(get);
    return *std::max_element(v.begin(), v.end());
  }
};

double wall(const MergeRun& r) {
  return r.wall_s;
}
double cpu(const MergeRun& r) {
  return r.cpu_s;
}
double estimate(const MergeRun& r) {
  return two_core_estimate(r.times);
}
double sift_prep_cpu(const MergeRun& r) {
  return r.times.features_cpu_s;
}
double thumbs_cpu(const MergeRun& r) {
  return r.times.thumbnails_cpu_s;
}
double release_cpu(const MergeRun& r) {
  return r.times.release_cpu_s;
}
double match_cpu(const MergeRun& r) {
  return sum(r.times.match_cpu_s);
}
double ransac_cpu(const MergeRun& r) {
  return sum(r.times.ransac_cpu_s);
}
double surface_cpu(const MergeRun& r) {
  return sum(r.times.surface_cpu_s);
}
double waves_wall(const MergeRun& r) {
  return sum(r.times.waves_s);
}
double waves_cpu(const MergeRun& r) {
  return sum(r.times.waves_cpu_s);
}
double truth_mm(const MergeRun& r) {
  return 1000 * r.truth_rms;
}
double surface_mm(const MergeRun& r) {
  return 1000 * r.surface_rms;
}

// The table docs/accuracy-cost.md quotes, on stderr.
void print_table(const std::vector<Row>& rows, double load_min, double load_max,
                 std::size_t rounds) {
  const Row& two = rows[0];
  std::fprintf(stderr,
               "\n%zu rounds, load average %.1f-%.1f; medians [min-max]; CPU = process CPU "
               "time, every thread\n\n",
               rounds, load_min, load_max);
  std::fprintf(stderr,
               "| images | wall | CPU | two-core estimate | wall / 2 | rounds' own / 2 | "
               "CPU / 2 | estimate / 2 |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const Row& row : rows) {
    std::vector<double> paired;
    for (std::size_t r = 0; r < rounds; ++r)
      paired.push_back(row.runs[r].wall_s / two.runs[r].wall_s);
    std::fprintf(
        stderr,
        "| %s | %.2f s [%.2f-%.2f] | %.2f s | %.2f s | %.2fx | %.2fx [%.2f-%.2f] | %.2fx | "
        "%.2fx |\n",
        row.name.c_str(), row.med(wall), row.min(wall), row.max(wall), row.med(cpu),
        row.med(estimate), row.med(wall) / two.med(wall), median(paired),
        *std::min_element(paired.begin(), paired.end()),
        *std::max_element(paired.begin(), paired.end()), row.med(cpu) / two.med(cpu),
        row.med(estimate) / two.med(estimate));
  }
  std::fprintf(stderr,
               "\nWhere the CPU went (medians, seconds; per image / per registration in "
               "brackets)\n\n| images | SIFT + preparation | thumbnails | matching | RANSAC | "
               "surface stage | release | waves (wall / CPU) |\n| --- | --- | --- | --- | --- | "
               "--- | --- | --- |\n");
  for (const Row& row : rows) {
    const double n = static_cast<double>(row.runs.front().times.match_cpu_s.size());
    const std::size_t waves = row.runs.front().times.waves_s.size();
    std::fprintf(stderr,
                 "| %s | %.2f (%.3f) | %.3f | %.2f (%.3f) | %.3f | %.2f (%.3f) | %.3f | %zu: %.2f "
                 "/ %.2f |\n",
                 row.name.c_str(), row.med(sift_prep_cpu), row.med(sift_prep_cpu) / n,
                 row.med(thumbs_cpu), row.med(match_cpu), row.med(match_cpu) / (n - 1),
                 row.med(ransac_cpu), row.med(surface_cpu), row.med(surface_cpu) / (n - 1),
                 row.med(release_cpu), waves, row.med(waves_wall), row.med(waves_cpu));
  }
  std::fprintf(stderr, "\nResiduals (worst image; worst and best round)\n\n");
  for (const Row& row : rows)
    std::fprintf(stderr,
                 "  %s images: truth RMS %.2f / %.2f mm, surface RMS %.2f / %.2f mm, fewest tie "
                 "points %d\n",
                 row.name.c_str(), row.max(truth_mm), row.min(truth_mm), row.max(surface_mm),
                 row.min(surface_mm), row.runs.front().tie_points);
  std::fprintf(stderr, "\n");
}

void BM_MergeInterleaved(benchmark::State& state) {
  const std::vector<std::vector<double>> offsets{
      {0.0, -1.0},
      {0.0, -1.0, 1.0, -2.0, 2.0},
      {0.0, -0.5, 0.5, -1.0, 1.0, -1.5, 1.5, -2.0, 2.0, -2.5}};
  std::vector<Row> rows{{"2", {}}, {"5", {}}, {"10", {}}};
  std::vector<std::vector<rp::FaceImage>> images;
  for (const auto& o : offsets) images.push_back(face_images(o));
  const auto rounds = static_cast<std::size_t>(state.range(0));
  rp::MultiImageOptions options;
  options.feature_max_width = static_cast<int>(state.range(1));
  double load_min = 1e9, load_max = 0;
  for (auto _ : state) {
    state.counters["cold2_s"] = run_merge(images[0], options).wall_s;
    for (std::size_t k = 1; k < images.size(); ++k) run_merge(images[k], options);
    for (std::size_t r = 0; r < rounds; ++r) {
      const double load = load_average();
      load_min = std::min(load_min, load);
      load_max = std::max(load_max, load);
      std::fprintf(stderr, "round %zu (load %.1f):", r + 1, load);
      for (std::size_t m = 0; m < images.size(); ++m) {
        const std::size_t k = (m + r) % images.size();
        rows[k].runs.push_back(run_merge(images[k], options));
        const MergeRun& run = rows[k].runs.back();
        std::fprintf(stderr, "  %s images %.2f s (CPU %.2f s, estimate %.2f s)",
                     rows[k].name.c_str(), run.wall_s, run.cpu_s, estimate(run));
      }
      std::fprintf(stderr, "\n");
    }
  }
  print_table(rows, load_min, load_max, rounds);
  const Row& two = rows[0];
  for (const Row& row : rows) {
    const std::string& k = row.name;
    state.counters["t" + k + "_s"] = row.med(wall);
    state.counters["cpu" + k + "_s"] = row.med(cpu);
    state.counters["est" + k + "_s"] = row.med(estimate);
    state.counters["truth" + k + "_mm"] = row.max(truth_mm);
    if (&row == &two) continue;
    state.counters["ratio" + k] = row.med(wall) / two.med(wall);
    state.counters["ratio" + k + "_cpu"] = row.med(cpu) / two.med(cpu);
    state.counters["ratio" + k + "_est"] = row.med(estimate) / two.med(estimate);
  }
  state.counters["load_min"] = load_min;
  state.counters["load_max"] = load_max;
}
// The default (tie points' SIFT at 600 px), and the photographs' own width.
BENCHMARK(BM_MergeInterleaved)
    ->ArgNames({"rounds", "width"})
    ->Args({9, 600})
    ->Args({5, 1200})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
