// The block's motion after failure (core/mechanics/dynamics): time per
// simulated second and the error against closed forms, against the step
// tolerance (rel_tol; abs_tol = rel_tol / 100), with the presets' kind of
// step cap (0.01 s) and without one (1 s: the tolerance alone decides):
//   slab: a 4 x 3 x 1.5 m slab on a 35-degree joint, friction 20, for
//     1 s: x = 1/2 g (sin 35 - tan 20 cos 35) t^2;
//   wedge: the symmetric wedge (joints 60/135, 60/225, friction 20) for
//     1 s: a = g.s - mu (N1 + N2) / m along the intersection s;
//   column: a leaning 1 x 1 x 4 m column on a rough level joint turning
//     about its edge for 0.6 s: error of the angular velocity against
//     1/2 I_edge w^2 = m g (drop of the centroid), times L / sqrt(g L)
//     (a speed at the block's size).
// Counters: err (largest error of a sample: m, or m/s of the fastest
// point for the column), err_rel (/ L, or / sqrt(g L)),
// steps, evaluations; the time is per simulated second.
#include <cmath>
#include <memory>

#include <benchmark/benchmark.h>

#include "core/blocks/mass_properties.h"
#include "core/common/units.h"
#include "core/mechanics/dynamics/block_dynamics.h"
#include "tests/support/mechanics_blocks.h"

namespace {

namespace mech = rockface::mechanics;
using namespace rockface;
using mech::testing::Slab;

constexpr double kG = 9.81;
constexpr double kRelTol[] = {1e-4, 1e-6, 1e-8, 1e-10};

std::vector<double> friction(const blocks::Polyhedron& p, double deg) {
  std::vector<double> f(p.planes().size(), 0.0);
  for (size_t i = 0; i < f.size(); ++i)
    if (p.planes()[i].kind == blocks::PlaneKind::Joint) f[i] = deg;
  return f;
}

constexpr double kMaxStep[] = {0.01, 1.0};

mech::DynamicsOptions options(const benchmark::State& state, double duration) {
  const auto tol = state.range(0);
  mech::DynamicsOptions o;
  o.rel_tol = kRelTol[tol];
  o.abs_tol = kRelTol[tol] / 100;
  o.max_step = kMaxStep[state.range(1)];
  o.duration = duration;
  o.sample = 0.05;
  return o;
}

// err: m (slab, wedge) or m/s (column); scale: the block's size L, or
// sqrt(g L) for a speed.
void report(benchmark::State& state, const mech::BlockDynamics& d, double err, double scale,
            double duration) {
  state.counters["err"] = err;
  state.counters["err_rel"] = err / scale;
  state.counters["steps"] = d.steps;
  state.counters["evaluations"] = d.evaluations;
  state.counters["rel_tol"] = kRelTol[state.range(0)];
  state.counters["max_step"] = kMaxStep[state.range(1)];
  state.SetLabel("per simulated s: x" + std::to_string(1.0 / duration));
}

void BM_DynamicsSlab(benchmark::State& state) {
  const Slab slab;
  const blocks::Polyhedron block = slab.block();
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  const kinematics::Effects e = mech::testing::gravity();
  const double duration = 1.0;
  mech::BlockDynamics d;
  for (auto _ : state)
    d = mech::simulate_block_motion(block, mass, e, friction(block, 20), options(state, duration));
  const double a =
      kG * (std::sin(deg_to_rad(35)) - std::tan(deg_to_rad(20)) * std::cos(deg_to_rad(35)));
  double err = 0;
  for (const auto& s : d.samples)
    err = std::max(err, std::abs((s.centroid - d.samples[0].centroid).dot(slab.d()) -
                                 0.5 * a * s.time * s.time));
  report(state, d, err, block.size(), duration);
}

void BM_DynamicsWedge(benchmark::State& state) {
  const blocks::Polyhedron block = mech::testing::wedge();
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  const kinematics::Effects e = mech::testing::gravity();
  const double duration = 1.0;
  mech::BlockDynamics d;
  for (auto _ : state)
    d = mech::simulate_block_motion(block, mass, e, friction(block, 20), options(state, duration));
  const Eigen::Vector3d n1 = block.planes()[0].inward_normal(),
                        n2 = block.planes()[1].inward_normal();
  Eigen::Vector3d s = n1.cross(n2).normalized();
  if (s.z() > 0) s = -s;
  const Eigen::Vector3d g(0, 0, -kG);
  Eigen::Matrix<double, 3, 2> m;
  m << n1, n2;
  const Eigen::Vector2d n = m.colPivHouseholderQr().solve(-(g - g.dot(s) * s));
  const double a = g.dot(s) - std::tan(deg_to_rad(20)) * (n(0) + n(1));
  double err = 0;
  for (const auto& smp : d.samples)
    err = std::max(
        err, ((smp.centroid - d.samples[0].centroid) - 0.5 * a * smp.time * smp.time * s).norm());
  report(state, d, err, block.size(), duration);
}

blocks::Polyhedron leaning_column() {
  using blocks::PlaneKind;
  using mech::testing::bounded;
  using mech::testing::bounding;
  const mech::testing::Placement at;
  const Eigen::Vector3d lean = Eigen::Vector3d(1, 0, -0.4).normalized();
  return bounded("column",
                 {bounding(0, "J1", PlaneKind::Joint, {0, 0, 1}, {0, 0, 0}, at),
                  bounding(1, "top", PlaneKind::FreeFace, {0, 0, -1}, {0, 0, 4}, at),
                  bounding(2, "L1", PlaneKind::FreeFace, lean, {0, 0, 0}, at),
                  bounding(3, "L2", PlaneKind::FreeFace, -lean, {1, 0, 0}, at),
                  bounding(4, "S1", PlaneKind::FreeFace, {0, 1, 0}, {0, 0, 0}, at),
                  bounding(5, "S2", PlaneKind::FreeFace, {0, -1, 0}, {0, 1, 0}, at)},
                 at);
}

void BM_DynamicsColumn(benchmark::State& state) {
  const blocks::Polyhedron block = leaning_column();
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  const kinematics::Effects e = mech::testing::gravity();
  const double duration = 0.6;
  mech::BlockDynamics d;
  for (auto _ : state)
    d = mech::simulate_block_motion(block, mass, e, friction(block, 60), options(state, duration));
  const Eigen::Vector3d pivot(1, 0.5, 0), axis = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d r0 = mass.centroid - pivot;
  const double i_edge =
      axis.dot(mass.inertia * axis) + mass.mass * (r0 - r0.dot(axis) * axis).squaredNorm();
  double err = 0;
  for (const auto& s : d.samples) {
    const double drop = d.samples[0].centroid.z() - s.centroid.z();
    const double w = std::sqrt(2 * mass.mass * kG * drop / i_edge);
    err = std::max(err, std::abs(s.angular_velocity.norm() - w) * block.size());
  }
  report(state, d, err, std::sqrt(kG * block.size()), duration);
}

// The slab over the edge of its joint: the time it starts to tip (an event
// found by bisection) against the closed form sqrt(2 (a/2 - mu t/2) / acc).
void BM_DynamicsSlabTips(benchmark::State& state) {
  const Slab slab;
  const blocks::Polyhedron block = slab.block();
  const blocks::MassProperties mass = blocks::mass_properties(block, 2700);
  const kinematics::Effects e = mech::testing::gravity();
  const double duration = 1.2;
  mech::BlockDynamics d;
  for (auto _ : state)
    d = mech::simulate_block_motion(block, mass, e, friction(block, 20), options(state, duration));
  const double mu = std::tan(deg_to_rad(20));
  const double acc = kG * (std::sin(deg_to_rad(35)) - mu * std::cos(deg_to_rad(35)));
  const double tip = std::sqrt(2 * (slab.a / 2 - mu * slab.t / 2) / acc);
  double err = INFINITY;
  for (const auto& ev : d.events)
    if (ev.kind == "rotates") err = std::abs(ev.time - tip);
  // A time error times the speed there: metres of travel.
  report(state, d, err * acc * tip, block.size(), duration);
}

}  // namespace

BENCHMARK(BM_DynamicsSlabTips)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DynamicsSlab)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DynamicsWedge)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DynamicsColumn)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
