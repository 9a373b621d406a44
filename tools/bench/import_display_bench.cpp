// "Full resolution for measuring, decimated for the display" (issue 43): how
// far the display copies of an imported scan are cut down, and what the dip
// and dip direction measured on them would cost against the full-resolution
// surface that measuring uses (docs/accuracy-cost.md, "An imported scan's
// display copies").
//
// The scan: the stepped face of tests/support/stepped_face.h (strips 0.75 m
// wide alternately on set A, 60/220, and set B, 60/140, 9 m wide and 4.5 m
// high, about 10 m north of the scanner), sampled on a jittered grid, each
// point moved along the scanner's line of sight by Gaussian ranging noise
// (2 mm, a terrestrial scanner's at 10 m), written as a binary PLY at UTM
// coordinates and imported by the program's own import (read, 2.5D mesh,
// virtual view, stored). The face stays the same size: more points are a
// denser scan.
//
// Each surface's triangles against the true face: how far their centroids
// lie off it (RMS, 99th percentile; the display's clustering cell).
// Each surface: the stored mesh (what `measure`, `propose`, the tablet's
// traces and Find traces use), and its display copies: the tablet's Model
// view at its budgets (`rockface ui --max-triangles`: 50 k, 200 k, 400 k the
// default, 1.6 M; ui/view3d/display_mesh.h) and the office's 3D face (40 k
// triangles, firmware-app/office/office_pages.h). On each:
//   - an area on every strip (its vertices 10 cm inside the strip's edges),
//     its plane as measuring fits an area (plane_of_points): the worst dip
//     and dip direction error over the strips against their true planes;
//   - the facets of each preset (fast / standard / precise facet options):
//     strips found (a facet whose normal lies within 2 degrees of the strip's
//     and whose centroid lies on it) and the worst dip / dip direction error
//     of the facets found.
// Time and memory: the import (per size), each copy's decimation and its
// bytes, each preset's facet search.
//
// Sizes: 250 k points by default (a few seconds); more with
// --points=1000000,4000000 (given before the benchmark's own flags).
#include <unistd.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/measure/facets/facet_options.h"
#include "core/measure/facets/facets.h"
#include "core/measure/plane_measurement.h"
#include "firmware-app/import/import_surface.h"
#include "firmware-app/measure/measure_models.h"
#include "firmware-app/office/office_pages.h"
#include "storage/project/project_store.h"
#include "tests/support/stepped_face.h"
#include "ui/view3d/display_mesh.h"

namespace {

namespace fs = std::filesystem;
namespace rm = rockface::measure;
namespace rt = rockface::test;
using rockface::rad_to_deg;

constexpr double kRangeNoiseM = 0.002;
const Eigen::Vector3d kUtm(276771, 5151636, 2385);  // the file's coordinates: UTM + local
constexpr double kHalfWidth = 4.5, kZFrom = -2.0, kZTo = 2.5;
constexpr double kInsideM = 0.10;  // an area's margin inside its strip

const rt::SteppedTruth& truth() {
  static const rt::SteppedTruth t;
  return t;
}

// The strips (planes and x-ranges) of the stepped face; the lattice is not
// used here (a small one is built with them).
const std::vector<rt::Facet>& strips() {
  static const std::vector<rt::Facet> s =
      rt::stepped_face(truth(), 40, 30, 0.0, 2, kHalfWidth, kZFrom, kZTo).facets;
  return s;
}

double peak_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return 0;
}
void reset_peak() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The scan as a binary PLY (x y z double, red green blue), at UTM
// coordinates; returns the points written (local, before the offset).
fs::path write_scan(std::size_t count, const fs::path& dir) {
  const double area = 2 * kHalfWidth * (kZTo - kZFrom);
  const double spacing = std::sqrt(area / static_cast<double>(count));
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> jitter(-0.3 * spacing, 0.3 * spacing);
  std::normal_distribution<double> noise(0, kRangeNoiseM);
  std::vector<double> xyz;
  xyz.reserve(3 * count + 300);
  for (double z0 = kZFrom + spacing / 2; z0 < kZTo; z0 += spacing)
    for (double x0 = -kHalfWidth + spacing / 2; x0 < kHalfWidth; x0 += spacing) {
      const double x = std::clamp(x0 + jitter(rng), -kHalfWidth, kHalfWidth - 1e-9);
      const double z = z0 + jitter(rng);
      const auto strip = std::find_if(strips().begin(), strips().end(),
                                      [&](const rt::Facet& f) { return x < f.x_to; });
      const Eigen::Vector3d& n = strip->plane.normal;
      const double y = (strip->plane.offset - n.x() * x - n.z() * z) / n.y();
      // The scanner at the origin: ranging noise along its line of sight.
      const Eigen::Vector3d p(x, y, z);
      const Eigen::Vector3d q = p + noise(rng) * p.normalized() + kUtm;
      xyz.insert(xyz.end(), {q.x(), q.y(), q.z()});
    }
  const std::size_t n = xyz.size() / 3;
  const fs::path file = dir / ("scan-" + std::to_string(count) + ".ply");
  std::ofstream out(file, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << n
      << "\nproperty double x\nproperty double y\nproperty double z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  const std::uint8_t grey[3] = {150, 140, 130};
  for (std::size_t i = 0; i < n; ++i) {
    out.write(reinterpret_cast<const char*>(&xyz[3 * i]), 3 * sizeof(double));
    out.write(reinterpret_cast<const char*>(grey), 3);
  }
  return file;
}

struct Imported {
  fs::path dir, project;
  rockface::app::ImportResult result;
  rockface::app::LoadedModel model;  // the stored surface, as measuring loads it
  rockface::storage::Mesh stored;    // the stored mesh record, as the tablet's view loads it
  double import_s = 0, import_peak_mb = 0;
};

// One import per size, kept for every copy's benchmark.
Imported& imported(std::size_t count) {
  static std::map<std::size_t, std::unique_ptr<Imported>> done;
  auto& slot = done[count];
  if (slot) return *slot;
  slot = std::make_unique<Imported>();
  Imported& m = *slot;
  m.dir = fs::temp_directory_path() /
          ("rockface-import-display-" + std::to_string(::getpid()) + "-" + std::to_string(count));
  fs::remove_all(m.dir);
  fs::create_directories(m.dir);
  const fs::path scan = write_scan(count, m.dir);
  m.project = m.dir / "scan.rockface";
  rockface::storage::ProjectInfo info;
  info.name = "display copies";
  rockface::storage::ProjectStore store = rockface::storage::ProjectStore::create(m.project, info);
  rockface::app::ImportRequest request;
  request.file = scan;
  request.view_from = kUtm;  // the scanner
  reset_peak();
  const auto start = std::chrono::steady_clock::now();
  m.result = rockface::app::import_surface(store, request);
  m.import_s = seconds_since(start);
  m.import_peak_mb = peak_mb();
  fs::remove(scan);
  m.model = rockface::app::load_stored_model(store, {}, m.result.model, 1);
  m.stored = store.load_model(m.result.model).mesh;
  return m;
}

// The file's local frame (the strips') from the project's.
Eigen::Vector3d local(const Imported& m, const Eigen::Vector3d& stored) {
  return stored + m.result.project_datum - kUtm;
}

double dipdir_difference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

struct Orientation {
  double dip = 0, dipdir = 0;
};
Orientation orientation_of(const Eigen::Vector3d& normal) {
  const auto o = rockface::geometry::plane_orientation(normal);
  return {rad_to_deg(o.dip), rad_to_deg(o.dipdir)};
}
Orientation true_orientation(std::size_t strip) {
  return strip % 2 == 0 ? Orientation{truth().dip, truth().dipdir}
                        : Orientation{truth().dip, 360 - truth().dipdir};
}

struct Errors {
  double dip = 0, dipdir = 0;
  int found = 0;
};

// An area on every strip, fitted as measuring fits a picked area.
Errors area_errors(const Imported& m, const rockface::photogrammetry::SurfaceMesh& mesh,
                   const rm::MeasureSettings& settings) {
  Errors e;
  for (std::size_t k = 0; k < strips().size(); ++k) {
    const auto& s = strips()[k];
    std::vector<Eigen::Vector3d> points;
    for (const auto& v : mesh.vertices) {
      const Eigen::Vector3d p = local(m, v);
      if (p.x() > s.x_from + kInsideM && p.x() < s.x_to - kInsideM && p.z() > kZFrom + kInsideM &&
          p.z() < kZTo - kInsideM)
        points.push_back(v);
    }
    if (points.size() < 3) continue;
    const rm::PlaneEstimate plane = rm::plane_of_points(points, settings);
    const Orientation got = orientation_of(plane.fit.normal), want = true_orientation(k);
    e.dip = std::max(e.dip, std::abs(got.dip - want.dip));
    e.dipdir = std::max(e.dipdir, dipdir_difference(got.dipdir, want.dipdir));
    ++e.found;
  }
  return e;
}

// The facets of a preset matched to the strips.
Errors facet_errors(const Imported& m, const rm::FacetSearch& search) {
  Errors e;
  std::vector<char> found(strips().size(), 0);
  for (const auto& f : search.facets) {
    const Eigen::Vector3d c = local(m, f.centroid);
    for (std::size_t k = 0; k < strips().size(); ++k) {
      const auto& s = strips()[k];
      if (c.x() < s.x_from || c.x() > s.x_to) continue;
      const double angle = rad_to_deg(std::acos(std::min(
          1.0, std::abs(f.plane.fit.normal.normalized().dot(s.plane.normal.normalized())))));
      if (angle > 2.0) continue;
      const Orientation got = orientation_of(f.plane.fit.normal), want = true_orientation(k);
      e.dip = std::max(e.dip, std::abs(got.dip - want.dip));
      e.dipdir = std::max(e.dipdir, dipdir_difference(got.dipdir, want.dipdir));
      found[k] = 1;
    }
  }
  e.found = static_cast<int>(std::count(found.begin(), found.end(), 1));
  return e;
}

// How far a surface's triangles lie off the true face: the distance of
// each triangle's centroid from the nearest strip plane about it (the
// strip under it and its neighbours), mm: RMS and the 99th percentile.
std::pair<double, double> off_face_mm(const Imported& m,
                                      const rockface::photogrammetry::SurfaceMesh& mesh) {
  std::vector<double> d;
  d.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d c =
        local(m, (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3);
    double best = 1e9;
    for (const auto& s : strips())
      if (c.x() > s.x_from - 0.5 && c.x() < s.x_to + 0.5)
        best = std::min(best, std::abs(s.plane.normal.dot(c) - s.plane.offset));
    d.push_back(best * 1000);
  }
  if (d.empty()) return {0, 0};
  double sum = 0;
  for (const double v : d) sum += v * v;
  const auto at = d.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(d.size() - 1));
  std::nth_element(d.begin(), at, d.end());
  return {std::sqrt(sum / static_cast<double>(d.size())), *at};
}

// A display copy as a surface to measure on (vertices back in the project
// frame, the display's float offsets from its centre added to it).
rockface::photogrammetry::SurfaceMesh surface_of(const Eigen::Vector3d& centre,
                                                 const std::vector<float>& positions,
                                                 const std::vector<std::uint32_t>& indices) {
  rockface::photogrammetry::SurfaceMesh s;
  for (std::size_t i = 0; i + 2 < positions.size(); i += 3)
    s.vertices.push_back(centre +
                         Eigen::Vector3d(positions[i], positions[i + 1], positions[i + 2]));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
    s.triangles.push_back({static_cast<int>(indices[t]), static_cast<int>(indices[t + 1]),
                           static_cast<int>(indices[t + 2])});
  return s;
}

// The office's face bytes ("RFM1", office_pages.h) as a surface.
rockface::photogrammetry::SurfaceMesh surface_of(const rockface::app::office_web::FaceMesh& face) {
  const std::uint8_t* b = face.bytes.data();
  std::uint32_t n = 0, t = 0, has_uv = 0;
  double origin[3];
  std::memcpy(&n, b + 4, 4);
  std::memcpy(&t, b + 8, 4);
  std::memcpy(&has_uv, b + 12, 4);
  std::memcpy(origin, b + 16, 24);
  std::size_t at = 40;
  std::vector<float> xyz(3 * n);
  std::memcpy(xyz.data(), b + at, 12 * n);
  at += 12 * n + (has_uv ? 8 * n : 0);
  std::vector<std::uint32_t> index(3 * t);
  std::memcpy(index.data(), b + at, 12 * t);
  return surface_of(Eigen::Vector3d(origin[0], origin[1], origin[2]), xyz, index);
}

constexpr std::size_t kFull = 0, kOffice = 1;  // copies that are not a tablet budget

void BM_ImportDisplayCopy(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const auto copy = static_cast<std::size_t>(state.range(1));
  Imported& m = imported(count);
  rm::MeasureSettings settings;
  settings.point_sigma = m.model.point_sigma;
  settings.correlation_length = m.model.correlation_length;
  rockface::photogrammetry::SurfaceMesh decimated;
  double decimate_s = 0, bytes = 0, cell = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    if (copy == kOffice) {
      rockface::storage::ProjectStore store = rockface::storage::ProjectStore::open(m.project);
      const auto face = rockface::app::office_web::face_mesh(store, m.result.visit, 40000);
      decimate_s = seconds_since(start);
      bytes = static_cast<double>(face.bytes.size());
      decimated = surface_of(face);
    } else if (copy != kFull) {
      const rockface::ui::DisplayMesh d = rockface::ui::make_display_mesh(m.stored, copy);
      decimate_s = seconds_since(start);
      bytes =
          static_cast<double>(d.positions.size() * 4 + d.texcoords.size() * 4 + d.colours.size() +
                              d.indices.size() * 4 + d.turning_indices.size() * 4);
      cell = d.cell;
      decimated = surface_of(d.centre, d.positions, d.indices);
    }
    state.SetIterationTime(std::max(decimate_s, 1e-9));
  }
  const rockface::photogrammetry::SurfaceMesh& surface = copy == kFull ? m.model.mesh : decimated;
  state.counters["points"] = static_cast<double>(m.result.points);
  state.counters["spacing_mm"] = m.result.point_spacing_m * 1000;
  state.counters["noise_mm"] = m.model.point_sigma * 1000;
  state.counters["import_s"] = m.import_s;
  state.counters["import_peak_MB"] = m.import_peak_mb;
  state.counters["triangles"] = static_cast<double>(surface.triangles.size());
  state.counters["decimate_s"] = decimate_s;
  state.counters["copy_MB"] = bytes / 1e6;
  const auto [rms, p99] = off_face_mm(m, surface);
  state.counters["off_face_rms_mm"] = rms;
  state.counters["off_face_p99_mm"] = p99;
  state.counters["cell_mm"] = cell * 1000;
  const Errors area = area_errors(m, surface, settings);
  state.counters["area_dip_err"] = area.dip;
  state.counters["area_dipdir_err"] = area.dipdir;
  for (const auto preset :
       {rockface::Preset::fast, rockface::Preset::standard, rockface::Preset::precise}) {
    const std::string name(rockface::preset_name(preset));
    rockface::NoProgress progress;
    reset_peak();
    const auto start = std::chrono::steady_clock::now();
    const rm::FacetSearch search =
        rm::find_facets(surface, settings, rm::facet_options(preset), progress);
    state.counters[name + "_s"] = seconds_since(start);
    state.counters[name + "_peak_MB"] = peak_mb();
    const Errors e = facet_errors(m, search);
    state.counters[name + "_found"] = e.found;
    state.counters[name + "_dip_err"] = e.dip;
    state.counters[name + "_dipdir_err"] = e.dipdir;
  }
  state.counters["strips"] = static_cast<double>(strips().size());
}

std::vector<std::size_t> sizes_from(int& argc, char** argv) {
  std::vector<std::size_t> sizes;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--points=", 0) == 0) {
      std::stringstream list(a.substr(9));
      for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::stoul(item));
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  if (sizes.empty()) sizes = {250'000};
  return sizes;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::size_t> sizes = sizes_from(argc, argv);
  const std::vector<std::pair<std::string, std::size_t>> copies = {
      {"full", kFull},          {"office_40k", kOffice},          {"tablet_50k", 50'000},
      {"tablet_200k", 200'000}, {"tablet_400k_default", 400'000}, {"tablet_1600k", 1'600'000}};
  for (const std::size_t n : sizes)
    for (const auto& [name, copy] : copies)
      benchmark::RegisterBenchmark(
          ("BM_ImportDisplayCopy/" + std::to_string(n) + "/" + name).c_str(), BM_ImportDisplayCopy)
          ->Args({static_cast<std::int64_t>(n), static_cast<std::int64_t>(copy)})
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kSecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for (const std::size_t n : sizes)
    fs::remove_all(
        fs::temp_directory_path() /
        ("rockface-import-display-" + std::to_string(::getpid()) + "-" + std::to_string(n)));
  return 0;
}
