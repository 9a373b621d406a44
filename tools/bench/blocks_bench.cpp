// Blocks: time of the mass properties and of the complete single-block
// analysis (construction from half-spaces, mass properties, finiteness with
// cone margins, effects, mode and factor of safety) against the number of
// faces: prisms over regular n-gons resting on an inclined joint, n + 2
// faces from 5 to 40 (and a tetrahedron for 4).
#include <cmath>
#include <memory>
#include <numbers>

#include <benchmark/benchmark.h>

#include "core/blocks/construction.h"
#include "core/blocks/mass_properties.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/kinematics/effects/effect_water.h"

namespace {

using rockface::blocks::HalfSpaceInput;
using rockface::blocks::PlaneKind;
using rockface::geometry::HalfSpace;

// Bounding half-space from the normal pointing into the block.
HalfSpaceInput bounding(int index, PlaneKind kind, const Eigen::Vector3d& inward,
                        const Eigen::Vector3d& point) {
  HalfSpaceInput h;
  h.index = index;
  h.name = "P" + std::to_string(index);
  h.kind = kind;
  const auto o = rockface::geometry::plane_orientation(inward);
  h.plane = rockface::geometry::Plane::from_orientation(o, point);
  h.side = h.plane.normal.dot(inward) > 0 ? HalfSpace::Upper : HalfSpace::Lower;
  return h;
}

// A block with `faces` faces: a prism over a regular (faces - 2)-gon of
// radius 1 m and height 0.5 m, its base a joint dipping 35 degrees, the
// other faces free; faces = 4 gives a tetrahedron on the joint.
std::vector<HalfSpaceInput> block_halfspaces(int faces) {
  const Eigen::Vector3d n = rockface::geometry::plane_normal({35 * std::numbers::pi / 180, 2.0});
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  std::vector<HalfSpaceInput> h{bounding(0, PlaneKind::Joint, n, Eigen::Vector3d::Zero())};
  const int sides = faces == 4 ? 3 : faces - 2;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * std::numbers::pi * k / sides;
    const Eigen::Vector3d radial = std::cos(a) * u + std::sin(a) * v;
    // For the tetrahedron the sides lean in to meet at an apex.
    const Eigen::Vector3d inward =
        faces == 4 ? Eigen::Vector3d(-radial - 0.5 * n) : Eigen::Vector3d(-radial);
    h.push_back(bounding(k + 1, PlaneKind::FreeFace, inward, radial));
  }
  if (faces != 4) h.push_back(bounding(sides + 1, PlaneKind::FreeFace, -n, 0.5 * n));
  return h;
}

void BM_MassProperties(benchmark::State& state) {
  const auto c = rockface::blocks::build_convex_block("b", block_halfspaces(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(rockface::blocks::mass_properties(*c.polyhedron, 2700));
  state.counters["faces"] = static_cast<double>(c.polyhedron->faces().size());
  state.counters["vertices"] = static_cast<double>(c.polyhedron->vertices().size());
}

void BM_CompleteBlockAnalysis(benchmark::State& state) {
  const auto h = block_halfspaces(state.range(0));
  rockface::kinematics::Effects effects;
  effects.push_back(
      std::make_unique<rockface::kinematics::GravityEffect>(Eigen::Vector3d(0, 0, -9.81)));
  effects.push_back(std::make_unique<rockface::kinematics::WaterEffect>(
      9810, Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d::UnitZ()));
  int faces = 0;
  for (auto _ : state) {
    const auto c = rockface::blocks::build_convex_block("b", h);
    rockface::kinematics::BlockAnalysisInput in;
    in.density = 2700;
    in.strengths.assign(c.polyhedron->planes().size(), {30 * std::numbers::pi / 180, 5e3});
    in.effects = &effects;
    in.uncertainty = std::numbers::pi / 180;
    benchmark::DoNotOptimize(rockface::kinematics::analyse_block(*c.polyhedron, in));
    faces = static_cast<int>(c.polyhedron->faces().size());
  }
  state.counters["faces"] = faces;
}

}  // namespace

BENCHMARK(BM_MassProperties)
    ->Arg(4)
    ->Arg(5)
    ->Arg(6)
    ->Arg(8)
    ->Arg(12)
    ->Arg(20)
    ->Arg(30)
    ->Arg(40)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CompleteBlockAnalysis)
    ->Arg(4)
    ->Arg(5)
    ->Arg(6)
    ->Arg(8)
    ->Arg(12)
    ->Arg(20)
    ->Arg(30)
    ->Arg(40)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
