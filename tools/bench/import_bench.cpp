// `rockface import` of a scanner's cloud (issue 43): the time and the peak
// memory of reading a LAS file, meshing it (CGAL 2.5D Delaunay, holes kept),
// drawing its virtual view and storing it, per million points. Each size runs
// the real binary as a child process, so the peak (the child's maximum
// resident set, wait4) is the import's own: the tablet must hold a
// 10-million-point cloud in 2 GB.
//
// The cloud: a rough tunnel face (4 x 3 m per million points' density kept
// at 2 mm spacing: the face grows with the count) at UTM coordinates, LAS
// 1.4 point format 7, written here before the timing. And a scan of a whole
// round (walls, roof, invert and the face of the sample heading, the design
// surface with 3 mm of noise, the spacing set by the count) imported into a
// project with the tunnel: meshed on the tunnel's developed view.
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

#include "storage/project/project_store.h"
#include "storage/scene/scene.h"

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

std::vector<char> las_header(std::uint64_t n, const double offset[3], const double lo[3],
                             const double hi[3], double scale) {
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
    put<double>(header, 179 + 16 * k, hi[k]);
    put<double>(header, 187 + 16 * k, lo[k]);
  }
  put<std::uint64_t>(header, 247, n);
  return header;
}

fs::path sample_file(const char* name) {
  return fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples" / name;
}

// A scan of the sample heading's round of about `count` points: its walls
// from 2 m behind the face to the face (chainage 110 to 112), every
// `spacing` of chainage and outline, and the face inside the design
// outline, on the design surface with 3 mm of noise, in survey coordinates.
fs::path write_round_las(std::size_t count) {
  const fs::path file =
      fs::temp_directory_path() / ("import-bench-round-" + std::to_string(count) + ".las");
  if (fs::exists(file)) return file;
  const rockface::storage::Scene scene =
      rockface::storage::load_scene(sample_file("tunnel-drive.scene.json").string());
  const auto& profile = scene.tunnel->record.profile;
  const auto alignment = scene.tunnel->record.alignment(Eigen::Vector3d::Zero());
  const double from = 110.0, face = 112.0;
  // The face's area: about the design outline's (a horseshoe 6 x 5.5 m).
  const double area = (face - from) * profile.perimeter() + 28.0;
  const double spacing = std::sqrt(area / static_cast<double>(count));
  const double scale = 1e-4;
  const Eigen::Vector3d origin = alignment.frame_at(face).to_local(0, 0);
  const double offset[3] = {std::floor(origin.x()), std::floor(origin.y()), std::floor(origin.z())};
  const double lo[3] = {offset[0] - 20, offset[1] - 20, offset[2] - 20};
  const double hi[3] = {offset[0] + 20, offset[1] + 20, offset[2] + 20};
  std::vector<char> header = las_header(0, offset, lo, hi, scale);
  std::ofstream out(file, std::ios::binary);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> jitter(-0.25 * spacing, 0.25 * spacing);
  std::normal_distribution<double> noise(0, 0.003);
  std::vector<char> rec(36, 0);
  std::uint64_t n = 0;
  const auto write = [&](const Eigen::Vector3d& p) {
    for (int k = 0; k < 3; ++k)
      put<std::int32_t>(
          rec, 4 * k,
          static_cast<std::int32_t>(std::lround((p[k] + noise(rng) - offset[k]) / scale)));
    for (int k = 0; k < 3; ++k) put<std::uint16_t>(rec, 30 + 2 * k, 150 * 256);
    out.write(rec.data(), 36);
    ++n;
  };
  const double perimeter = profile.perimeter();
  for (double c0 = from; c0 < face; c0 += spacing)
    for (double s0 = 0; s0 < perimeter; s0 += spacing) {
      const double c = std::min(face, c0 + jitter(rng)),
                   s = std::fmod(s0 + jitter(rng) + perimeter, perimeter);
      const Eigen::Vector2d uv = profile.point_at_length(s);
      write(alignment.frame_at(c).to_local(uv.x(), uv.y()));
    }
  const auto at_face = alignment.frame_at(face);
  for (double u = -4; u <= 4; u += spacing)
    for (double v = -4; v <= 5; v += spacing) {
      const Eigen::Vector2d p(u + jitter(rng), v + jitter(rng));
      const Eigen::Vector2d d = p - profile.ray_centre();
      if (d.norm() > 0.97 * profile.radius_toward(std::atan2(d.y(), d.x()))) continue;
      write(at_face.to_local(p.x(), p.y()));
    }
  header = las_header(n, offset, lo, hi, scale);
  out.seekp(0);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  return file;
}

// `rockface ARGS` as a child process; its peak resident set (MB), or -1
// when it failed.
double run_child(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string bin = std::string(ROCKFACE_BINARY_DIR) + "/rockface";
    if (!freopen("/dev/null", "w", stdout)) _exit(127);
    std::vector<char*> argv{const_cast<char*>(bin.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(bin.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return static_cast<double>(usage.ru_maxrss) / 1024;  // kB on Linux
}

void BM_ImportRoundLas(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const fs::path las = write_round_las(count);
  const fs::path project = fs::temp_directory_path() / "import-bench-round.rockface";
  for (auto _ : state) {
    fs::remove(project);
    {
      rockface::storage::ProjectInfo info;
      info.name = "round scan";
      rockface::storage::ProjectStore::create(project, info);
    }
    if (run_child({"tunnel", project.string(), "--alignment",
                   sample_file("tunnel-drive.alignment.csv").string(), "--profile",
                   sample_file("tunnel-drive.profile.json").string()}) < 0) {
      state.SkipWithError("rockface tunnel failed");
      break;
    }
    const auto start = std::chrono::steady_clock::now();
    const double peak = run_child({"import", project.string(), las.string()});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (peak < 0) {
      state.SkipWithError("rockface import failed");
      break;
    }
    state.SetIterationTime(seconds);
    state.counters["peak_MB"] = peak;
    state.counters["s_per_Mpoint"] = seconds / (static_cast<double>(count) / 1e6);
    state.counters["file_MB"] = static_cast<double>(fs::file_size(las)) / 1e6;
    state.counters["project_MB"] = static_cast<double>(fs::file_size(project)) / 1e6;
  }
  fs::remove(project);
}

BENCHMARK(BM_ImportRoundLas)
    ->Arg(1'000'000)
    ->Arg(10'000'000)
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

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
