// The face as a tunnel lights it: what each imaging effect costs in
// accuracy. The synthetic faceted face (tests/integration/lighting/
// lit_face.h: 1200 x 800, fast preset, pole and compass) under each effect
// alone at rising strength, and under all of them ("bad tunnel day");
// errors against the render's truth, or the refusal.
//
// Counters: scale_err_pct (the registered surface against the truth),
// north_err_deg, dip_err_deg (worst facet normal), target_px (worst target
// centre), refused (1: the pipeline refused the pair by name, see the
// log line), texture_grey (image_contrast.h's measure of the left image).
#include <cstdio>
#include <functional>
#include <string>

#include <benchmark/benchmark.h>

#include "core/photogrammetry/matching/image_contrast.h"
#include "tests/support/lit_face.h"

using namespace rockface;
using namespace rockface::testing;
using Effects = camera::SyntheticEffects;

namespace {

void run_case(benchmark::State& state, const std::string& name, const Effects& e) {
  LitFaceOutcome o;
  for (auto _ : state) o = reconstruct_lit_face(lit_face(e));
  const auto c = photogrammetry::measure_contrast(o.render.images[0]);
  state.counters["texture_grey"] = c.texture_grey;
  state.counters["refused"] = o.truth ? 0 : 1;
  state.counters["shading_spread"] = o.shading.spread;
  state.counters["normalised"] = o.shading_normalised ? 1 : 0;
  if (o.truth) {
    state.counters["scale_err_pct"] = 100 * o.truth->scale_error;
    state.counters["north_err_deg"] = o.truth->north_error_deg;
    state.counters["dip_err_deg"] = o.truth->worst_facet_deg;
    state.counters["target_px"] = o.truth->worst_target_px;
  } else {
    std::fprintf(stderr, "%s: refused: %s\n", name.c_str(), o.refusal.c_str());
  }
}

void reg(const std::string& name, std::function<Effects()> make) {
  benchmark::RegisterBenchmark(name.c_str(),
                               [make, name](benchmark::State& s) { run_case(s, name, make()); })
      ->Iterations(1)
      ->Unit(benchmark::kSecond);
}

Effects bad_day() {
  Effects e;
  e.flash = camera::SyntheticFlash{1.0};
  e.lamps.push_back({Eigen::Vector3d(-3.5, 3.0, 3.0), 30.0});
  e.vignetting = 1.0;
  e.sensor = camera::SyntheticSensor{3200};
  e.jpeg_quality = 80;
  const FacetTruth& f = synthetic_facets()[2];
  camera::SyntheticRegion wet{"W1", {}}, sprayed{"S1", {}};
  for (auto [x, z] : {std::pair{1.8, -2.0}, {3.6, -2.0}, {3.6, 0.0}, {1.8, 0.0}})
    wet.polygon.emplace_back(x, facet_y(f, x, z), z);
  const FacetTruth& g = synthetic_facets()[0];
  for (auto [x, z] : {std::pair{-3.8, 2.0}, {-1.8, 2.0}, {-1.8, 3.3}, {-3.8, 3.3}})
    sprayed.polygon.emplace_back(x, facet_y(g, x, z), z);
  e.wet.push_back({wet, 0.8, 60, 0.6});
  e.shotcrete.push_back({sprayed, 0.55});
  e.dust = camera::SyntheticDust{3.912 / 60.0, 0.3};
  return e;
}

const bool registered = [] {
  reg("none", [] { return Effects{}; });
  for (double i : {0.25, 0.5, 1.0, 2.0})
    reg("flash/intensity:" + std::to_string(i).substr(0, 4), [i] {
      Effects e;
      e.flash = camera::SyntheticFlash{i};
      return e;
    });
  for (double i : {30.0, 60.0, 100.0})
    reg("lamp_between_stations/intensity:" + std::to_string(int(i)), [i] {
      Effects e;
      e.lamps.push_back({Eigen::Vector3d(0, 0.05, 0.55), i});
      return e;
    });
  for (double v : {1.0, 2.0, 3.0})
    reg("vignetting/strength:" + std::to_string(int(v)), [v] {
      Effects e;
      e.vignetting = v;
      return e;
    });
  for (double iso : {800.0, 3200.0, 6400.0, 12800.0, 25600.0, 51200.0})
    reg("sensor/iso:" + std::to_string(int(iso)), [iso] {
      Effects e;
      e.sensor = camera::SyntheticSensor{iso};
      return e;
    });
  for (int q : {95, 80, 50, 20})
    reg("jpeg/quality:" + std::to_string(q), [q] {
      Effects e;
      e.jpeg_quality = q;
      return e;
    });
  for (double s : {0.4, 0.8, 1.6})
    reg("wet_middle_facet/specular:" + std::to_string(s).substr(0, 3), [s] {
      Effects e;
      const FacetTruth& f = synthetic_facets()[1];
      camera::SyntheticRegion r{"W1", {}};
      for (auto [x, z] : {std::pair{-1.2, -2.0}, {1.2, -2.0}, {1.2, 3.0}, {-1.2, 3.0}})
        r.polygon.emplace_back(x, facet_y(f, x, z), z);
      e.wet.push_back({r, s, 60, 0.6});
      return e;
    });
  for (double w : {1.0, 2.0})
    reg("shotcrete_on_left_facet/width_m:" + std::to_string(int(w)), [w] {
      Effects e;
      const FacetTruth& f = synthetic_facets()[0];
      camera::SyntheticRegion r{"S1", {}};
      for (auto [x, z] : {std::pair{-1.5 - w, -2.0}, {-1.5, -2.0}, {-1.5, 3.0}, {-1.5 - w, 3.0}})
        r.polygon.emplace_back(x, facet_y(f, x, z), z);
      e.shotcrete.push_back({r, 0.55});
      return e;
    });
  for (double v : {200.0, 100.0, 60.0, 40.0, 30.0, 25.0, 20.0})
    reg("dust_iso800/visibility_m:" + std::to_string(int(v)), [v] {
      Effects e;
      e.sensor = camera::SyntheticSensor{800};
      e.dust = camera::SyntheticDust{3.912 / v, 0.35};
      return e;
    });
  reg("flash+iso3200+jpeg80", [] {
    Effects e;
    e.flash = camera::SyntheticFlash{1.0};
    e.sensor = camera::SyntheticSensor{3200};
    e.jpeg_quality = 80;
    return e;
  });
  reg("bad_tunnel_day", bad_day);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
