// `rockface import` of a scanner's cloud (issue 43): the time and the peak
// memory of reading a LAS file, meshing it (CGAL 2.5D Delaunay, holes kept),
// drawing its virtual view and storing it, per million points. Each size runs
// the real binary as a child process, so the peak (the child's maximum
// resident set, wait4) is the import's own: the tablet must hold a
// 10-million-point cloud in 2 GB.
//
// The cloud: a rough tunnel face (4 x 3 m per million points' density kept
// at 2 mm spacing: the face grows with the count) at UTM coordinates, LAS
// 1.4 point format 7, written here before the timing.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

template <typename T>
void put(std::vector<char>& b, std::size_t at, T v) {
  std::memcpy(b.data() + at, &v, sizeof(T));
}

// A face of `count` points on a jittered 2 mm grid, 4:3, with a relief of
// a few centimetres, at E 276771 N 5151636 Z 2385.
fs::path write_face_las(std::size_t count) {
  const fs::path file =
      fs::temp_directory_path() / ("import-bench-" + std::to_string(count) + ".las");
  if (fs::exists(file)) return file;
  const double spacing = 0.002, scale = 1e-4;
  const auto columns = static_cast<std::size_t>(std::sqrt(static_cast<double>(count) * 4 / 3));
  const std::size_t rows = count / columns;
  const std::size_t n = rows * columns;
  const double offset[3] = {276771, 5151636, 2385};
  std::vector<char> header(375, 0);
  std::memcpy(header.data(), "LASF", 4);
  header[24] = 1;
  header[25] = 4;
  put<std::uint16_t>(header, 94, 375);
  put<std::uint32_t>(header, 96, 375);
  header[104] = 7;
  put<std::uint16_t>(header, 105, 36);
  for (int k = 0; k < 3; ++k) {
    put<double>(header, 131 + 8 * k, scale);
    put<double>(header, 155 + 8 * k, offset[k]);
  }
  // Bounds: the face's extent plus its relief and jitter.
  const double width = columns * spacing, height = rows * spacing;
  put<double>(header, 179, offset[0] + width + 1);
  put<double>(header, 187, offset[0] - 1);
  put<double>(header, 195, offset[1] + 1);
  put<double>(header, 203, offset[1] - 1);
  put<double>(header, 211, offset[2] + height + 1);
  put<double>(header, 219, offset[2] - 1);
  put<std::uint64_t>(header, 247, n);
  std::ofstream out(file, std::ios::binary);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> jitter(-0.3 * spacing, 0.3 * spacing);
  std::normal_distribution<double> noise(0, 0.001);
  std::vector<char> rec(36, 0);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c) {
      const double x = c * spacing + jitter(rng), z = r * spacing + jitter(rng);
      const double y = 0.05 * std::sin(3 * x) * std::cos(2 * z) + noise(rng);
      const double p[3] = {x, y, z};
      for (int k = 0; k < 3; ++k)
        put<std::int32_t>(rec, 4 * k, static_cast<std::int32_t>(std::lround(p[k] / scale)));
      for (int k = 0; k < 3; ++k)
        put<std::uint16_t>(rec, 30 + 2 * k, static_cast<std::uint16_t>(128 * 256 + 40 * k * 256));
      out.write(rec.data(), 36);
    }
  return file;
}

void BM_ImportLas(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const fs::path las = write_face_las(count);
  const fs::path project = fs::temp_directory_path() / "import-bench.rockface";
  for (auto _ : state) {
    fs::remove(project);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
      const std::string bin = std::string(ROCKFACE_BINARY_DIR) + "/rockface";
      if (!freopen("/dev/null", "w", stdout)) _exit(127);
      execl(bin.c_str(), bin.c_str(), "import", project.c_str(), las.c_str(),
            static_cast<char*>(nullptr));
      _exit(127);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      state.SkipWithError("rockface import failed");
      break;
    }
    state.SetIterationTime(seconds);
    state.counters["peak_MB"] = static_cast<double>(usage.ru_maxrss) / 1024;  // kB on Linux
    state.counters["s_per_Mpoint"] = seconds / (static_cast<double>(count) / 1e6);
    state.counters["file_MB"] = static_cast<double>(fs::file_size(las)) / 1e6;
    state.counters["project_MB"] = static_cast<double>(fs::file_size(project)) / 1e6;
  }
  fs::remove(project);
}

// 1, 10 and 30 million points; one run each (tens of seconds to minutes).
BENCHMARK(BM_ImportLas)
    ->Arg(1'000'000)
    ->Arg(10'000'000)
    ->Arg(30'000'000)
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
