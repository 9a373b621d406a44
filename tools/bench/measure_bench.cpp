// Measuring on the 3D image: what accuracy costs in time (docs/accuracy-cost.md,
// "Measuring on the 3D image").
//
// - pick latency on a 24 Mpx model: the lattice mesh a 6000 x 4000 left
//   photograph gives at the standard preset (1.55 M vertices, 3.1 M
//   triangles), over the three facets of
//   tests/support/synthetic_face.h, picked at random pixels;
//   and the time to build its BVH;
// - least-cost (semi-automatic) tracing against trace length, on a
//   noisy rock-like photograph with a 2 px dark trace, darkness cost;
//   counter: mean distance of the path to the true line (px);
// - plane-fit error against the number of picked points: a trace across
//   two facets (0.1 m of relief off its line), points with 7 mm noise
//   (sigma_Z of the demo replay), Monte Carlo over 400 traces; counters:
//   RMS angle error, the fit's predicted sigma (deg);
// - plane-fit error against the reconstruction preset: the synthetic face
//   rendered 3000 x 2000 with two joints drawn, reconstructed with each
//   preset and registered by pole and compass; J1 tapped where the renderer
//   drew it (as tests/integration/measure does); the time is that of the
//   reconstruction (the measurement itself is milliseconds).
#include <algorithm>
#include <cmath>
#include <random>

#include <benchmark/benchmark.h>
#include <opencv2/imgproc.hpp>

#include "camera/synthetic_renderer.h"
#include "core/common/preset.h"
#include "core/common/units.h"
#include "core/measure/least_cost_trace.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/plane_measurement.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "tests/support/synthetic_truth.h"

namespace rm = rockface::measure;
namespace rp = rockface::photogrammetry;
namespace rg = rockface::geometry;
using rockface::deg_to_rad;
using rockface::rad_to_deg;

namespace {

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

// ---- a 24 Mpx model -------------------------------------------------------

struct LatticeModel {
  rp::SurfaceMesh mesh;
  rm::PhotoView view;
};

// The faceted face seen from the left station of a 6000 x 4000 camera: one
// vertex every `step` px where a ray meets a facet, noise sigma 7 mm along
// the ray, two triangles per lattice cell.
const LatticeModel& lattice_24mpx() {
  static const LatticeModel model = [] {
    LatticeModel m;
    const auto scene = rockface::testing::synthetic_face(6000, 4000);
    m.view.name = "left";
    m.view.camera = rockface::camera::rendered_intrinsics(scene);
    m.view.pose = rockface::camera::station_pose(scene.stations[0], "bench");
    // One lattice node every 3 px: the face fills ~57 % of the frame, so
    // this gives the 1.5 M vertices and 3.1 M triangles of the standard
    // preset's model of the 24 Mpx tunnel face (docs/accuracy-cost.md, UI).
    const double step = 3.0;
    const int cols = static_cast<int>(6000 / step), rows = static_cast<int>(4000 / step);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0, 0.007);
    std::vector<int> index(static_cast<std::size_t>(cols) * rows, -1);
    const auto& facets = rockface::testing::synthetic_facets();
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        const Eigen::Vector2d px(c * step, r * step);
        const rm::Ray ray = rm::ray_through_pixel(m.view, px, "bench");
        double best = 1e9;
        for (const auto& f : facets) {
          const Eigen::Vector3d n = rockface::testing::facet_normal(f);
          const Eigen::Vector3d p0(0.5 * (f.x_from + f.x_to), 10.0, 0.5);
          const double t = n.dot(p0 - ray.origin) / n.dot(ray.direction);
          const Eigen::Vector3d hit = ray.origin + t * ray.direction;
          if (t > 0 && hit.x() >= f.x_from && hit.x() <= f.x_to && hit.z() > -2.5 && hit.z() < 3.5)
            best = std::min(best, t);
        }
        if (best > 1e8) continue;
        index[static_cast<std::size_t>(r) * cols + c] = static_cast<int>(m.mesh.vertices.size());
        m.mesh.vertices.push_back(ray.origin + (best + noise(rng)) * ray.direction);
        m.mesh.pixels.push_back(px.cast<float>());
      }
    for (int r = 0; r + 1 < rows; ++r)
      for (int c = 0; c + 1 < cols; ++c) {
        const int a = index[static_cast<std::size_t>(r) * cols + c],
                  b = index[static_cast<std::size_t>(r) * cols + c + 1],
                  d = index[static_cast<std::size_t>(r + 1) * cols + c],
                  e = index[static_cast<std::size_t>(r + 1) * cols + c + 1];
        if (a >= 0 && b >= 0 && d >= 0) m.mesh.triangles.push_back({a, d, b});
        if (b >= 0 && d >= 0 && e >= 0) m.mesh.triangles.push_back({b, d, e});
      }
    m.mesh.texture_width = 6000;
    m.mesh.texture_height = 4000;
    return m;
  }();
  return model;
}

void BM_PickerBuild24Mpx(benchmark::State& state) {
  const LatticeModel& m = lattice_24mpx();
  for (auto _ : state) {
    rm::MeshPicker picker(m.mesh);
    benchmark::DoNotOptimize(picker.node_count());
  }
  state.counters["vertices"] = static_cast<double>(m.mesh.size());
  state.counters["triangles"] = static_cast<double>(m.mesh.triangles.size());
}
BENCHMARK(BM_PickerBuild24Mpx)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Pick24Mpx(benchmark::State& state) {
  const LatticeModel& m = lattice_24mpx();
  static const rm::MeshPicker picker(m.mesh);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 5999), v(0, 3999);
  std::int64_t hits = 0;
  for (auto _ : state) {
    const auto hit = picker.pick(m.view, {u(rng), v(rng)}, "bench");
    hits += hit ? 1 : 0;
    benchmark::DoNotOptimize(hit);
  }
  state.counters["hit_pct"] = 100.0 * static_cast<double>(hits) / state.iterations();
}
BENCHMARK(BM_Pick24Mpx)->Unit(benchmark::kMicrosecond);

// A trace of 8 taps over ~600 px densified every 2 px and fitted: what a
// tap on the tablet costs once the trace is long.
void BM_MeasureTrace24Mpx(benchmark::State& state) {
  const LatticeModel& m = lattice_24mpx();
  static const rm::MeshPicker picker(m.mesh);
  std::vector<Eigen::Vector2d> taps;
  for (int k = 0; k < 8; ++k) taps.emplace_back(2600 + 100.0 * k, 1800 + 30.0 * k);
  rm::MeasureSettings s;
  s.point_sigma = 0.007;
  for (auto _ : state) {
    const auto t = rm::measure_trace(picker, m.view, "T", taps, s, "bench");
    benchmark::DoNotOptimize(t.plane.fit.normal);
  }
}
BENCHMARK(BM_MeasureTrace24Mpx)->Unit(benchmark::kMillisecond);

// ---- least-cost tracing ---------------------------------------------------

// 2000 x 1200 px of speckled rock (grey 60-200, blurred) with a 2 px dark
// trace along a gentle curve, sensor noise sigma 4.
struct TracePhoto {
  cv::Mat image;
  std::vector<Eigen::Vector2d> line;  // the trace's centre, one point per px of x
};

const TracePhoto& trace_photo() {
  static const TracePhoto photo = [] {
    TracePhoto p;
    cv::Mat rock(1200, 2000, CV_8UC1);
    cv::RNG rng(5);
    rng.fill(rock, cv::RNG::UNIFORM, 60, 200);
    cv::GaussianBlur(rock, rock, cv::Size(0, 0), 1.5);
    for (int x = 0; x < 2000; ++x)
      p.line.emplace_back(x, 600 + 120 * std::sin(x / 400.0) + 0.05 * x);
    for (std::size_t i = 1; i < p.line.size(); ++i)
      cv::line(rock, cv::Point2d(p.line[i - 1].x(), p.line[i - 1].y()),
               cv::Point2d(p.line[i].x(), p.line[i].y()), cv::Scalar(35), 2, cv::LINE_AA);
    cv::Mat noise(rock.size(), CV_8SC1);
    rng.fill(noise, cv::RNG::NORMAL, 0, 4);
    cv::add(rock, noise, rock, cv::noArray(), CV_8U);
    cv::cvtColor(rock, p.image, cv::COLOR_GRAY2BGR);
    return p;
  }();
  return photo;
}

double distance_to(const std::vector<Eigen::Vector2d>& line, const Eigen::Vector2d& q) {
  double best = 1e9;
  const int x0 = std::max(0, static_cast<int>(q.x()) - 20),
            x1 = std::min(static_cast<int>(line.size()) - 1, static_cast<int>(q.x()) + 20);
  for (int i = x0 + 1; i <= x1; ++i) {
    const Eigen::Vector2d a = line[i - 1], b = line[i];
    const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - q).norm());
  }
  return best;
}

void BM_LeastCostTrace(benchmark::State& state) {
  const TracePhoto& p = trace_photo();
  const int length = static_cast<int>(state.range(0));  // along x
  rm::TraceRequest r;
  r.from = p.line[100];
  r.to = p.line[100 + length];
  r.cost = rm::TraceCost::Darkness;
  rm::TracedPath path;
  for (auto _ : state) path = rm::trace_between(p.image, nullptr, r, "bench");
  double sum = 0;
  for (const auto& q : path.pixels) sum += distance_to(p.line, q);
  state.counters["length_px"] = (r.to - r.from).norm();
  state.counters["path_px"] = static_cast<double>(path.pixels.size());
  state.counters["mean_dist_px"] = sum / static_cast<double>(path.pixels.size());
}
BENCHMARK(BM_LeastCostTrace)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Arg(1600)
    ->Unit(benchmark::kMillisecond);

// ---- plane fit against the number of points -------------------------------

// A joint (dip 55, dip direction 120) traced across a fold of the face: two
// facets meeting at x = 0 (dip directions 160 and 200, dip 80), the trace
// 2 m long, half on each; points with isotropic noise sigma.
void BM_PlaneFitVsPoints(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double sigma = 0.007;
  const Eigen::Vector3d joint = rg::plane_normal_deg(55, 120);
  const Eigen::Vector3d facet[2] = {rg::plane_normal_deg(80, 160), rg::plane_normal_deg(80, 200)};
  // The trace on each facet: the line joint x facet through the fold point.
  std::vector<Eigen::Vector3d> dir(2);
  for (int k = 0; k < 2; ++k) {
    dir[k] = joint.cross(facet[k]).normalized();
    if (dir[k].x() * (k == 0 ? -1 : 1) < 0) dir[k] = -dir[k];
  }
  std::mt19937 rng(11);
  std::normal_distribution<double> e(0, sigma);
  rm::MeasureSettings settings;
  settings.point_sigma = sigma;
  double sum_sq = 0, sum_sigma = 0;
  int trials = 0, known = 0;
  for (auto _ : state) {
    for (int trial = 0; trial < 400; ++trial) {
      std::vector<Eigen::Vector3d> pts, normals;
      for (int i = 0; i < n; ++i) {
        const double s = -1.0 + 2.0 * i / std::max(1, n - 1);  // -1 .. 1 m along the trace
        const int k = s < 0 ? 0 : 1;
        pts.push_back(std::abs(s) * dir[k] + Eigen::Vector3d(e(rng), e(rng), e(rng)));
        normals.push_back(-facet[k]);
      }
      const rm::PlaneEstimate p = rm::fit_trace_plane(pts, normals, settings);
      ++trials;
      if (!p.known) continue;
      ++known;
      const double err = angle_deg(p.fit.normal, joint);
      sum_sq += err * err;
      sum_sigma += rad_to_deg(p.sigma);
    }
  }
  state.counters["rms_err_deg"] = known ? std::sqrt(sum_sq / known) : NAN;
  state.counters["pred_sigma_deg"] = known ? sum_sigma / known : NAN;
  state.counters["known_pct"] = 100.0 * known / std::max(1, trials);
}
BENCHMARK(BM_PlaneFitVsPoints)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// ---- plane fit against the reconstruction preset --------------------------

struct Rendered {
  rockface::camera::SyntheticScene scene;
  rockface::camera::SyntheticRender render;
};

const Rendered& rendered_with_joints() {
  static const Rendered r = [] {
    Rendered r;
    r.scene = rockface::testing::synthetic_face(3000, 2000, true, 2.0);
    r.scene.joints.push_back({"J1", rg::plane_normal_deg(25, 30), {0.0, 10.0, 2.0}});
    rockface::NoProgress progress;
    r.render = rockface::camera::render_scene(r.scene, progress);
    return r;
  }();
  return r;
}

void BM_TracePlaneVsPreset(benchmark::State& state, const std::string& preset_name) {
  const Rendered& r = rendered_with_joints();
  const rp::ReconstructionPreset preset =
      rp::reconstruction_preset(rockface::parse_preset(preset_name, "bench preset"));
  rp::ReconstructionResult rec;
  for (auto _ : state) {
    rockface::NoProgress progress;
    rec = rp::reconstruct(r.render.images[0], r.render.images[1], r.render.intrinsics,
                          r.render.intrinsics, preset,
                          rockface::testing::pole_and_compass(r.scene, r.render, 0.0), progress);
  }
  // Taps: 8 per piece of J1's drawn trace (5 % off each end, 10 px inside).
  std::vector<Eigen::Vector2d> taps;
  for (const auto& t : r.render.traces) {
    std::vector<Eigen::Vector2d> px;
    const std::size_t n = t.left_image.size(), cut = n / 20;
    for (std::size_t i = cut; i + cut < n; ++i) {
      const auto& p = t.left_image[i];
      if (p.x() > 10 && p.y() > 10 && p.x() < r.render.intrinsics.width - 10 &&
          p.y() < r.render.intrinsics.height - 10)
        px.push_back(p);
    }
    if (px.size() < 2) continue;
    if (px.front().x() > px.back().x()) std::reverse(px.begin(), px.end());
    for (std::size_t i = 0; i < px.size(); i += std::max<std::size_t>(1, px.size() / 8))
      taps.push_back(px[i]);
  }
  std::sort(taps.begin(), taps.end(), [](const auto& a, const auto& b) { return a.x() < b.x(); });
  const rm::MeshPicker picker(rec.mesh);
  rm::MeasureSettings s;
  s.point_sigma = rec.accuracy.sigma_z;
  s.correlation_length = rec.point_spacing * preset.sgbm_block_size;
  try {
    const auto t = rm::measure_trace(picker, rm::left_view(rec.model_to_world, r.render.intrinsics),
                                     "J1", taps, s, "bench");
    state.counters["known"] = t.plane.known ? 1 : 0;
    state.counters["err_deg"] = angle_deg(t.plane.fit.normal, r.scene.joints[0].normal);
    state.counters["pred_sigma_deg"] = rad_to_deg(t.plane.sigma);
    state.counters["points"] = static_cast<double>(t.points.size());
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
  state.counters["sigma_Z_mm"] = rec.accuracy.sigma_z * 1000;
}
BENCHMARK_CAPTURE(BM_TracePlaneVsPreset, fast, std::string("fast"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_TracePlaneVsPreset, standard, std::string("standard"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_TracePlaneVsPreset, precise, std::string("precise"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
