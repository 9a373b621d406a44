// Facets on the 3D image: what the knobs cost and buy (docs/accuracy-cost.md,
// "Facets on the 3D image").
//
// The model: a 24 Mpx model, the lattice mesh a 6000 x 4000 left photograph
// gives at the standard reconstruction preset (dense matching at 1600 px:
// one vertex every 3.75 px, here every 4 px: 1500 x 1000 = 1.5 M vertices,
// 3.0 M triangles), of the stepped face of tests/support/stepped_face.h
// filling the photograph: strips 0.75 m wide alternately parallel to two
// joint sets (60/220 and 60/140) 10 m from the camera, 7 mm of noise along
// the rays (sigma_Z of the demo replay), correlated over the matching window
// as dense matching's is (model_24mpx).
//
// Counters: facets found; recall (strips found as a facet covering at
// least half of the strip's mapped area); precision (facets lying on a
// true strip: normal within 2 deg and centroid within 3 sigma of its
// plane); mean and worst orientation error of the facets against their
// strip's true plane (deg); sets found (truth: 2) and the worst spacing
// error (m); peak_MB: the process's resident high-water mark during the
// run (reset before it through /proc/self/clear_refs).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/preset.h"
#include "core/common/units.h"
#include "core/measure/facets/facet_sets.h"
#include "core/measure/facets/facets.h"
#include "tests/support/stepped_face.h"

namespace rm = rockface::measure;
namespace rt = rockface::test;
using rockface::rad_to_deg;

namespace {

constexpr double kSigma = 0.007;

const rt::SteppedTruth& truth() {
  static const rt::SteppedTruth t;
  return t;
}

// Dense matching's errors are not independent from point to point: they
// are shared over the matching window (5 px at the dense scale, about one
// lattice step here). The noise is a Gaussian random field along the rays,
// blurred over 2.5 lattice steps and scaled to sigma_Z = 7 mm.
const rt::FoldedFace& model_24mpx() {
  static const rt::FoldedFace f = [] {
    rt::FoldedFace face = rt::stepped_face(truth(), 6000, 4000, 0.0, 4, 7.0, -4.5, 5.5);
    const int cols = 1500, rows = 1000;
    cv::Mat field(rows, cols, CV_64F);
    cv::randn(field, 0.0, 1.0);
    cv::GaussianBlur(field, field, cv::Size(0, 0), 2.5);
    cv::Scalar mean, sd;
    cv::meanStdDev(field, mean, sd);
    auto& mesh = face.mesh;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const int c = std::clamp(static_cast<int>(mesh.pixels[i].x() / 4), 0, cols - 1);
      const int r = std::clamp(static_cast<int>(mesh.pixels[i].y() / 4), 0, rows - 1);
      const Eigen::Vector3d ray = (mesh.vertices[i] - face.view.pose.centre).normalized();
      mesh.vertices[i] += kSigma * (field.at<double>(r, c) - mean[0]) / sd[0] * ray;
    }
    return face;
  }();
  return f;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

void reset_peak() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

double peak_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return 0;
}

void run(benchmark::State& state, const rm::FacetOptions& options) {
  const rt::FoldedFace& face = model_24mpx();
  rm::MeasureSettings settings;
  settings.point_sigma = kSigma;
  // One independent point per matching window (as the propose workflow
  // counts them): the field's correlation, about five point spacings.
  settings.correlation_length = 5 * face.mesh.median_edge_length();
  rockface::NoProgress progress;
  rm::FacetSearch found;
  rm::FacetSets sets;
  reset_peak();
  for (auto _ : state) {
    found = rm::find_facets(face.mesh, settings, options, progress);
    sets = rm::facet_sets(found);
    benchmark::DoNotOptimize(sets);
  }
  const double peak = peak_mb();
  // Each strip's mapped area: the mesh triangles whose centre is on it.
  std::vector<double> strip_area(face.facets.size(), 0.0), found_area(face.facets.size(), 0.0);
  auto strip_of = [&](const Eigen::Vector3d& p) {
    for (std::size_t k = 0; k < face.facets.size(); ++k)
      if (p.x() >= face.facets[k].x_from && p.x() <= face.facets[k].x_to) return k;
    return face.facets.size();
  };
  const auto& mesh = face.mesh;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const std::size_t k = strip_of((a + b + c) / 3);
    if (k < face.facets.size()) strip_area[k] += 0.5 * (b - a).cross(c - a).norm();
  }
  double sum_error = 0, worst_error = 0;
  int on_truth = 0;
  for (const auto& f : found.facets) {
    const std::size_t k = strip_of(f.centroid);
    if (k >= face.facets.size()) continue;
    const double e = angle_deg(f.plane.fit.normal, face.facets[k].plane.normal);
    sum_error += e;
    worst_error = std::max(worst_error, e);
    if (e < 2.0 && std::abs(face.facets[k].plane.signed_distance(f.centroid)) < 3 * kSigma) {
      ++on_truth;
      found_area[k] = std::max(found_area[k], f.area);
    }
  }
  int recalled = 0;
  for (std::size_t k = 0; k < face.facets.size(); ++k)
    recalled += strip_area[k] > 0 && found_area[k] >= 0.5 * strip_area[k];
  int strips_seen = 0;
  for (double a : strip_area) strips_seen += a > 0;
  double spacing_error = 0;
  for (const auto& s : sets.sets)
    spacing_error =
        std::max(spacing_error, s.summary.spacing ? std::abs(*s.summary.spacing - truth().spacing())
                                                  : truth().spacing());
  const double n = static_cast<double>(found.facets.size());
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  state.counters["facets"] = n;
  state.counters["recall"] = strips_seen > 0 ? static_cast<double>(recalled) / strips_seen : 0;
  state.counters["precision"] = n > 0 ? on_truth / n : 0;
  state.counters["mean_err_deg"] = n > 0 ? sum_error / n : 0;
  state.counters["worst_err_deg"] = worst_error;
  state.counters["sets"] = static_cast<double>(sets.sets.size());
  state.counters["spacing_err_m"] = spacing_error;
  state.counters["peak_MB"] = peak;
}

void BM_Preset(benchmark::State& state) {
  const auto preset = static_cast<rockface::Preset>(state.range(0));
  state.SetLabel(std::string(rockface::preset_name(preset)));
  run(state, rm::facet_options(preset));
}
BENCHMARK(BM_Preset)
    ->Arg(static_cast<int>(rockface::Preset::fast))
    ->Arg(static_cast<int>(rockface::Preset::standard))
    ->Arg(static_cast<int>(rockface::Preset::precise))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// One knob at a time from the standard preset.
void BM_AngleTolerance(benchmark::State& state) {
  auto o = rm::facet_options(rockface::Preset::standard);
  o.angle_tolerance_deg = static_cast<double>(state.range(0));
  run(state, o);
}
BENCHMARK(BM_AngleTolerance)
    ->Arg(4)
    ->Arg(6)
    ->Arg(10)
    ->Arg(15)
    ->Arg(25)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

void BM_MinAreaCm2(benchmark::State& state) {
  auto o = rm::facet_options(rockface::Preset::standard);
  o.min_area_m2 = static_cast<double>(state.range(0)) / 1e4;
  run(state, o);
}
BENCHMARK(BM_MinAreaCm2)
    ->Arg(100)
    ->Arg(500)
    ->Arg(2000)
    ->Arg(10000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

void BM_PlanarityTenthSigmas(benchmark::State& state) {
  auto o = rm::facet_options(rockface::Preset::standard);
  o.planarity_in_sigmas = static_cast<double>(state.range(0)) / 10.0;
  run(state, o);
}
BENCHMARK(BM_PlanarityTenthSigmas)
    ->Arg(20)
    ->Arg(30)
    ->Arg(40)
    ->Arg(60)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

void BM_SmoothingPasses(benchmark::State& state) {
  auto o = rm::facet_options(rockface::Preset::standard);
  o.smoothing_passes = static_cast<int>(state.range(0));
  run(state, o);
}
BENCHMARK(BM_SmoothingPasses)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Arg(5)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
