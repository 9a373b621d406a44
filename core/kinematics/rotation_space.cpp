#include "core/kinematics/rotation_space.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/geometry/tolerances.h"
#include "core/kinematics/rotation_tolerances.h"

namespace rockface::kinematics {

namespace {

double safe_asin(double s) {
  return std::asin(std::clamp(s, -1.0, 1.0));
}

// Limit planes whose orientation is inside the measurement uncertainty: C - R
// within `uncertainty` of the joint normal (see rotation_space.h).
bool ill_posed(const LimitPlane& l, double uncertainty_rad) {
  return uncertainty_rad > 0 &&
         l.conditioning < std::sin(std::min(uncertainty_rad, std::numbers::pi / 2));
}

// The cone of the limit half-spaces, numerically repeated normals (faces
// sharing a plane, corners on one line from R) entered once: the margin
// search is O(m^4) in their number.
geometry::Cone limit_cone(const std::vector<LimitPlane>& limits, double uncertainty_rad,
                          bool drop_ill_posed) {
  std::vector<Eigen::Vector3d> normals;
  for (const auto& l : limits) {
    if (drop_ill_posed && ill_posed(l, uncertainty_rad)) continue;
    const bool seen = std::any_of(normals.begin(), normals.end(), [&](const Eigen::Vector3d& n) {
      return (n - l.normal).norm() < geometry::kSameRayRad;
    });
    if (!seen) normals.push_back(l.normal);
  }
  return geometry::Cone(normals);
}

// The exact margin of a cone with many half-spaces, by active sets: the
// margin of a subset is never below the margin of the whole (more
// half-spaces can only lower the max-min), so when the subset's optimal
// direction keeps every other half-space at least as far, it is the
// optimum of the whole. Otherwise the half-space it violates most joins the
// subset. Each step is geometry::Cone's exact O(k^4) search on k half-spaces,
// k staying small (the optimum is fixed by at most three of them), instead
// of O(m^4) on all m limit planes.
geometry::ConeMargin exact_margin(const geometry::Cone& cone) {
  const auto& all = cone.normals();
  constexpr size_t kDirect = 12;  // below this the direct search is as cheap
  if (all.size() <= kDirect) return cone.margin();
  std::vector<Eigen::Vector3d> active = {all.front()};
  std::vector<char> used(all.size(), 0);
  used[0] = 1;
  for (;;) {
    const geometry::ConeMargin m = geometry::Cone(active).margin();
    const double level = std::sin(m.angle);
    size_t worst = 0;
    double worst_dot = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < all.size(); ++i) {
      const double d = all[i].dot(m.direction);
      if (d < worst_dot) {
        worst_dot = d;
        worst = i;
      }
    }
    // Rounding of the dot products (~1e-16) is all that may separate the two.
    if (worst_dot >= level - 1e-15 || used[worst]) {
      geometry::ConeMargin result = m;
      result.angle = std::min(m.angle, safe_asin(worst_dot));
      return result;
    }
    used[worst] = 1;
    active.push_back(all[worst]);
  }
}

// min over the limit planes (those `keep` accepts) of asin(normal . u): how far
// the unit direction u is inside all of them; pi/2 when none constrains it.
template <class Keep>
double margin_of_axis(const std::vector<LimitPlane>& limits, const Eigen::Vector3d& u, Keep keep) {
  double m = std::numbers::pi / 2;
  for (const auto& l : limits)
    if (keep(l)) m = std::min(m, safe_asin(l.normal.dot(u)));
  return m;
}

// A verdict that also turns marginal when the limit planes inside the
// orientation uncertainty decide it: with and without them the sign differs.
geometry::Verdict decide_with_ill_posed(double with_all, double without_ill_posed,
                                        double uncertainty_rad) {
  geometry::Verdict v = geometry::decide(with_all, uncertainty_rad);
  if ((with_all > 0) != (without_ill_posed > 0)) v.marginal = true;
  return v;
}

}  // namespace

std::vector<LimitPlane> limit_planes(const RotationInput& in, const RotationTopology& topology,
                                     const Eigen::Vector3d& pivot, const std::vector<int>& exclude,
                                     int* void_count) {
  std::vector<LimitPlane> limits;
  int voids = 0;
  const double on_axis = kOnAxisRel * topology.size;
  for (int c = 0; c < static_cast<int>(in.vertices.size()); ++c) {
    if (std::find(exclude.begin(), exclude.end(), c) != exclude.end()) continue;
    const Eigen::Vector3d arm = in.vertices[c] - pivot;  // C - R
    const double arm_len = arm.norm();
    if (!(arm_len > on_axis)) continue;
    for (int p : topology.vertex_planes[c]) {
      if (!in.planes[p].joint) continue;
      const Eigen::Vector3d w = arm.cross(in.planes[p].inward_normal);  // (C - R) x n = n x (R - C)
      const double conditioning = w.norm() / arm_len;
      if (!(conditioning > kVoidLimitPlaneSin)) {
        ++voids;
        continue;
      }
      limits.push_back({c, p, w / w.norm(), conditioning});
    }
  }
  if (void_count) *void_count = voids;
  return limits;
}

CornerRotation corner_rotation(const RotationInput& in, const RotationTopology& topology,
                               int vertex, double uncertainty_rad) {
  CornerRotation r;
  r.vertex = vertex;
  const Eigen::Vector3d pivot = in.vertices[vertex];
  r.limits = limit_planes(in, topology, pivot, {vertex}, &r.void_limits);
  r.space = limit_cone(r.limits, uncertainty_rad, false);
  const geometry::ConeMargin m = exact_margin(r.space);
  r.signed_margin = m.angle;
  r.best_axis = m.direction;
  const bool any_ill_posed =
      std::any_of(r.limits.begin(), r.limits.end(),
                  [&](const LimitPlane& l) { return ill_posed(l, uncertainty_rad); });
  const double without = any_ill_posed
                             ? exact_margin(limit_cone(r.limits, uncertainty_rad, true)).angle
                             : r.signed_margin;
  r.rotatable = decide_with_ill_posed(r.signed_margin, without, uncertainty_rad);
  if (r.signed_margin >= -geometry::kAngleEpsRad) r.extreme_rays = r.space.edges(m.angle);

  // Sliding rotation about the block-side normal of each joint through R.
  for (int j : topology.vertex_planes[vertex]) {
    if (!in.planes[j].joint) continue;
    SlidingRotation s;
    s.plane = j;
    const Eigen::Vector3d& nj = in.planes[j].inward_normal;
    auto parallel_to_j = [&](int k) {
      return in.planes[k].inward_normal.cross(nj).norm() < kParallelJointsSin;
    };
    for (const auto& l : r.limits)
      if (l.plane != j && parallel_to_j(l.plane) &&
          std::find(s.also_sliding.begin(), s.also_sliding.end(), l.plane) == s.also_sliding.end())
        s.also_sliding.push_back(l.plane);
    s.signed_margin =
        margin_of_axis(r.limits, nj, [&](const LimitPlane& l) { return !parallel_to_j(l.plane); });
    const double s_without = margin_of_axis(r.limits, nj, [&](const LimitPlane& l) {
      return !parallel_to_j(l.plane) && !ill_posed(l, uncertainty_rad);
    });
    s.feasible = decide_with_ill_posed(s.signed_margin, s_without, uncertainty_rad);
    r.sliding.push_back(std::move(s));
  }
  return r;
}

EdgeRotation edge_rotation(const RotationInput& in, const RotationTopology& topology, int a, int b,
                           double uncertainty_rad) {
  EdgeRotation e;
  e.vertices = {std::min(a, b), std::max(a, b)};
  const Eigen::Vector3d pivot = in.vertices[a];
  const Eigen::Vector3d dir = (in.vertices[b] - pivot).normalized();
  std::vector<LimitPlane> limits = limit_planes(in, topology, pivot, {a, b});
  // Corners on the axis line (not only its end corners) stay where they are.
  const double on_axis = kOnAxisRel * topology.size;
  std::erase_if(limits, [&](const LimitPlane& l) {
    const Eigen::Vector3d arm = in.vertices[l.corner] - pivot;
    return !((arm - arm.dot(dir) * dir).norm() > on_axis);
  });
  auto all = [](const LimitPlane&) { return true; };
  auto well_posed = [&](const LimitPlane& l) { return !ill_posed(l, uncertainty_rad); };
  const double plus = margin_of_axis(limits, dir, all);
  const double minus = margin_of_axis(limits, -dir, all);
  e.axis = plus >= minus ? dir : Eigen::Vector3d(-dir);
  e.signed_margin = std::max(plus, minus);
  const double without =
      std::max(margin_of_axis(limits, dir, well_posed), margin_of_axis(limits, -dir, well_posed));
  e.rotatable = decide_with_ill_posed(e.signed_margin, without, uncertainty_rad);
  return e;
}

RotationAnalysis analyse_rotation(const RotationInput& in, double uncertainty_rad) {
  const RotationTopology topology = rotation_topology(in);
  RotationAnalysis result;
  for (int v = 0; v < static_cast<int>(in.vertices.size()); ++v)
    if (topology.is_static_point(in, v))
      result.corners.push_back(corner_rotation(in, topology, v, uncertainty_rad));
  for (const auto& edge : topology.edges)
    if (topology.is_boundary_edge(in, edge))
      result.edges.push_back(
          edge_rotation(in, topology, edge.vertices[0], edge.vertices[1], uncertainty_rad));
  return result;
}

}  // namespace rockface::kinematics
