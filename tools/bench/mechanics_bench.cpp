// Mechanics: the equilibrium path of single blocks (core/mechanics), FoS
// and time against the two knobs of the presets: contact points per joint
// face (contact_density, sub-divisions per triangle edge) and the
// continuation step. Rigid-plastic Coulomb joints (1e10 Pa/m, no dilation):
//   plane: a 4 x 3 x 1.5 m slab on a 35-degree joint, friction 40: the
//     limit point must be limit equilibrium's tan 40 / tan 35 = 1.198;
//   couple: a 4 x 4 x 0.5 m slab on a 20-degree joint, friction 35, turned
//     by a couple of 2 x W sin 20 x 3.6 m about the joint's normal: the
//     limit point is rotational and depends on how the contacts resolve
//     the base; its reference is density 16, step 0.01;
//   prism12: a 12-face block (prism over a regular 10-gon, radius 1 m,
//     height 0.5 m, on a 35-degree joint, friction 40) at the presets.
#include <cmath>
#include <memory>
#include <numbers>

#include <benchmark/benchmark.h>

#include "core/blocks/construction.h"
#include "core/blocks/mass_properties.h"
#include "core/common/preset.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/effects/effect_force.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/mechanics/equilibrium_path.h"
#include "tests/support/mechanics_blocks.h"

namespace {

namespace mech = rockface::mechanics;
using mech::testing::Slab;

constexpr double kRho = 2600;

struct Case {
  rockface::blocks::Polyhedron block;
  rockface::kinematics::Effects effects;
  double friction_deg;
};

Case plane_case() {
  Slab s;
  s.psi = 35;
  return {s.block(), mech::testing::gravity(), 40};
}

Case couple_case() {
  Slab s;
  s.psi = 20;
  s.a = 4;
  s.b = 4;
  s.t = 0.5;
  rockface::kinematics::Effects e = mech::testing::gravity();
  const double f = kRho * 9.81 * s.a * s.b * s.t * std::sin(20 * std::numbers::pi / 180);
  e.push_back(std::make_unique<rockface::kinematics::ForceEffect>(
      "f0", f * s.d(), s.at(0.5, 0.95, 0.5), rockface::kinematics::ForceFrame::Space));
  e.push_back(std::make_unique<rockface::kinematics::ForceEffect>(
      "f1", -f * s.d(), s.at(0.5, 0.05, 0.5), rockface::kinematics::ForceFrame::Space));
  return {s.block(), std::move(e), 35};
}

Case prism12_case() {
  using rockface::blocks::PlaneKind;
  const mech::testing::Placement at;
  const Eigen::Vector3d n = mech::testing::normal_deg(35, 115);
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  std::vector<rockface::blocks::HalfSpaceInput> h{
      mech::testing::bounding(0, "J", PlaneKind::Joint, n, Eigen::Vector3d::Zero(), at)};
  for (int k = 0; k < 10; ++k) {
    const double a = 2 * std::numbers::pi * k / 10;
    const Eigen::Vector3d radial = std::cos(a) * u + std::sin(a) * v;
    h.push_back(mech::testing::bounding(k + 1, "S" + std::to_string(k), PlaneKind::FreeFace,
                                        -radial, radial, at));
  }
  h.push_back(mech::testing::bounding(11, "T", PlaneKind::FreeFace, -n, 0.5 * n, at));
  return {mech::testing::bounded("prism12", h, at), mech::testing::gravity(), 40};
}

mech::EquilibriumPath run(const Case& c, const mech::MechanicsOptions& o) {
  const auto m = rockface::blocks::mass_properties(c.block, kRho);
  return mech::equilibrium_path(
      c.block, m, c.effects,
      mech::testing::laws(c.block, mech::testing::coulomb(c.friction_deg, 0, 1e10)), std::nullopt,
      o);
}

void report(benchmark::State& state, const mech::EquilibriumPath& r, double reference) {
  const double fos = r.fos_limit_point.value_or(NAN);
  state.counters["fos"] = fos;
  state.counters["rel_err"] = std::abs(fos - reference) / reference;
  state.counters["contacts"] = r.contacts;
  state.counters["steps"] = r.steps;
  state.counters["evals"] = r.residual_evaluations;
  state.counters["rotates"] = r.static_mode.rotates ? 1 : 0;
}

double couple_reference() {
  static const double ref = [] {
    mech::MechanicsOptions o;
    o.contact_density = 16;
    o.step = 0.01;
    return run(couple_case(), o).fos_limit_point.value_or(NAN);
  }();
  return ref;
}

const double kPlaneFos =
    std::tan(40 * std::numbers::pi / 180) / std::tan(35 * std::numbers::pi / 180);

void BM_PlaneDensity(benchmark::State& state) {
  const Case c = plane_case();
  mech::MechanicsOptions o;
  o.contact_density = static_cast<int>(state.range(0));
  mech::EquilibriumPath r;
  for (auto _ : state) r = run(c, o);
  report(state, r, kPlaneFos);
}

void BM_CoupleDensity(benchmark::State& state) {
  const Case c = couple_case();
  const double ref = couple_reference();
  mech::MechanicsOptions o;
  o.contact_density = static_cast<int>(state.range(0));
  mech::EquilibriumPath r;
  for (auto _ : state) r = run(c, o);
  report(state, r, ref);
}

void BM_CoupleStep(benchmark::State& state) {
  const Case c = couple_case();
  const double ref = couple_reference();
  mech::MechanicsOptions o;
  o.step = state.range(0) / 1000.0;
  mech::EquilibriumPath r;
  for (auto _ : state) r = run(c, o);
  state.counters["step"] = o.step;
  report(state, r, ref);
}

void BM_Prism12Preset(benchmark::State& state) {
  const Case c = prism12_case();
  const char* names[] = {"fast", "standard", "precise"};
  const mech::MechanicsOptions o =
      mech::mechanics_options(rockface::parse_preset(names[state.range(0)], "bench preset"));
  mech::EquilibriumPath r;
  for (auto _ : state) r = run(c, o);
  state.SetLabel(names[state.range(0)]);
  state.counters["faces"] = static_cast<double>(c.block.faces().size());
  report(state, r, kPlaneFos);
}

// The staged Barton-Bandis law (JRC 10, JCS 100 MPa, phi_b 30) on the
// plane slab: arg 0 the normal stiffness exponent (10: 1e10 Pa/m), arg 1
// the contact density, arg 2 the tangent of the path (0: the laws'
// consistent tangents, 1: forward differences, the earlier method).
void BM_BartonSlab(benchmark::State& state) {
  const Case c = plane_case();
  mech::MechanicsOptions o;
  o.contact_density = static_cast<int>(state.range(1));
  o.difference_tangent = state.range(2) == 1;
  const auto m = rockface::blocks::mass_properties(c.block, kRho);
  const auto laws = mech::testing::laws(
      c.block, mech::testing::barton(10, std::pow(10.0, static_cast<double>(state.range(0)))));
  mech::EquilibriumPath r;
  for (auto _ : state) r = mech::equilibrium_path(c.block, m, c.effects, laws, std::nullopt, o);
  state.SetLabel(o.difference_tangent ? "differences" : "consistent");
  report(state, r, r.fos_limit_point.value_or(NAN));
  state.counters["lambda_end"] = r.path.back().lambda;
  state.counters["rejected"] = r.rejected_steps;
  state.counters["flutter_from"] = r.flutter_lambda.value_or(NAN);
}

}  // namespace

BENCHMARK(BM_BartonSlab)
    ->Args({10, 2, 0})
    ->Args({10, 3, 0})
    ->Args({12, 2, 0})
    ->Args({12, 3, 0})
    ->Args({10, 2, 1})
    ->Args({10, 3, 1})
    ->Args({12, 2, 1})
    ->Args({12, 3, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_PlaneDensity)->Arg(1)->Arg(2)->Arg(3)->Arg(6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoupleDensity)->Arg(2)->Arg(3)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoupleStep)
    ->Arg(200)
    ->Arg(100)
    ->Arg(50)
    ->Arg(20)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Prism12Preset)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
