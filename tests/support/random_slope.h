#pragma once
// A dense random trace map on a benched slope, shared by the trace-map
// benchmark (tools/bench/faces_bench.cpp) and the tests that need a map with
// every kind of loop: five patches 40 m along strike, traces from three
// joint sets at random places with random lengths (fixed seed), each marked
// with a few millimetres of hand error.
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/units.h"
#include "core/faces/free_surface.h"
#include "core/faces/trace_plane.h"
#include "core/geometry/orientation.h"

namespace rockface::faces::testing {

using V = Eigen::Vector3d;

inline constexpr double kLength = 40;  // m along strike
inline constexpr double kSnap = 0.05;  // m, the scene default

inline std::vector<PatchInput> random_slope() {
  return {
      {"floor", {V(-10, 0, 0), V(0, 0, 0), V(0, kLength, 0), V(-10, kLength, 0)}},
      {"lower face", {V(0, 0, 0), V(3, 0, 6), V(3, kLength, 6), V(0, kLength, 0)}},
      {"bench", {V(3, 0, 6), V(8, 0, 6), V(8, kLength, 6), V(3, kLength, 6)}},
      {"upper face", {V(8, 0, 6), V(11, 0, 12), V(11, kLength, 12), V(8, kLength, 6)}},
      {"top", {V(11, 0, 12), V(21, 0, 12), V(21, kLength, 12), V(11, kLength, 12)}},
  };
}

inline TraceJoint joint_set(int k) {
  // Cross joints along the dip, a set dipping out of the faces, one into them.
  static const double dip[3] = {85, 35, 70}, dipdir[3] = {10, 265, 80};
  TraceJoint j;
  j.index = k;
  j.id = "J" + std::to_string(k + 1);
  j.orientation = {deg_to_rad(dip[k]), deg_to_rad(dipdir[k])};
  j.friction = deg_to_rad(32);
  return j;
}

inline std::vector<TraceInput> random_traces(const FreeSurface& surface, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1), jitter(-0.003, 0.003);
  std::uniform_int_distribution<int> set(0, 2), patch(0, 4);
  std::vector<TraceInput> traces;
  while (static_cast<int>(traces.size()) < n) {
    const SurfacePatch& P = surface.patches()[patch(rng)];
    // A random point of the patch: bilinear in its (rectangular) corners.
    const V a = P.polygon[0], b = P.polygon[1], d = P.polygon[3];
    const V centre = a + unit(rng) * (b - a) + unit(rng) * (d - a);
    const TraceJoint j = joint_set(set(rng));
    const V dir = geometry::plane_normal(j.orientation).cross(P.outward);
    if (dir.norm() < 0.1) continue;
    const double half = 1 + 3 * unit(rng);
    TraceInput t;
    t.id = "T" + std::to_string(traces.size() + 1);
    t.joint = j;
    for (double s : {-half, 0.0, half}) {
      V p = centre + s * dir.normalized() + jitter(rng) * P.e1 + jitter(rng) * P.e2;
      const Eigen::Vector2d q = P.to2d(p);
      if (!P.contains(q, 0)) continue;  // keep the marking on its patch
      t.points.push_back(p);
    }
    if (t.points.size() >= 2) traces.push_back(std::move(t));
  }
  return traces;
}

}  // namespace rockface::faces::testing
