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
// within `uncertainty` of the joint normal (see rotation_space.h). The sine
// of the uncertainty is taken once per rotation space (IllPosed), not once
// per limit plane.
struct IllPosed {
  explicit IllPosed(double uncertainty_rad)
      : active(uncertainty_rad > 0),
        below(active ? std::sin(std::min(uncertainty_rad, std::numbers::pi / 2)) : 0) {}
  bool operator()(const LimitPlane& l) const { return active && l.conditioning < below; }
  bool active;
  double below;
};

// The cone of the limit half-spaces, numerically repeated normals (faces
// sharing a plane, corners on one line from R) entered once: the margin
// search is O(m^4) in their number.
geometry::Cone limit_cone(const std::vector<LimitPlane>& limits, const IllPosed& ill_posed,
                          bool drop_ill_posed) {
  // A normal is left out when it is within kSameRayRad of one kept earlier
  // in the list. |dx| >= kSameRayRad already decides "not the same" (the
  // norm is at least |dx|), so in the order by x only runs of neighbours
  // closer than that in x can hold repeats (rare): only those are checked,
  // in list order.
  thread_local std::vector<std::pair<double, int>> by_x;  // scratch, reused
  thread_local std::vector<char> out;
  by_x.clear();
  for (int i = 0; i < static_cast<int>(limits.size()); ++i)
    if (!drop_ill_posed || !ill_posed(limits[i])) by_x.emplace_back(limits[i].normal.x(), i);
  std::sort(by_x.begin(), by_x.end());
  out.assign(limits.size(), 1);  // 1: left out (not taken or a repeat)
  for (const auto& [x, i] : by_x) out[i] = 0;
  for (size_t r = 0; r + 1 < by_x.size();) {
    size_t end = r + 1;
    while (end < by_x.size() && by_x[end].first - by_x[end - 1].first < geometry::kSameRayRad)
      ++end;
    if (end - r > 1) {
      std::vector<int> run;
      for (size_t k = r; k < end; ++k) run.push_back(by_x[k].second);
      std::sort(run.begin(), run.end());
      for (size_t k = 1; k < run.size(); ++k) {
        const LimitPlane& l = limits[run[k]];
        for (size_t e = 0; e < k && !out[run[k]]; ++e)
          out[run[k]] =
              !out[run[e]] &&
              std::abs(limits[run[e]].normal.x() - l.normal.x()) < geometry::kSameRayRad &&
              (limits[run[e]].normal - l.normal).norm() < geometry::kSameRayRad;
      }
    }
    r = end;
  }
  std::vector<Eigen::Vector3d> normals;
  normals.reserve(by_x.size());
  for (size_t i = 0; i < limits.size(); ++i)
    if (!out[i]) normals.push_back(limits[i].normal);
  // The limit planes' normals are unit (w / |w|, limit_planes()).
  return geometry::Cone::from_unit_normals(std::move(normals));
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
  size_t most = 0;
  for (const auto& planes : topology.vertex_planes) most += planes.size();
  limits.reserve(most);
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
      const double w_len = w.norm();
      const double conditioning = w_len / arm_len;
      if (!(conditioning > kVoidLimitPlaneSin)) {
        ++voids;
        continue;
      }
      limits.push_back({c, p, w / w_len, conditioning});
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
  const IllPosed ill_posed(uncertainty_rad);
  r.space = limit_cone(r.limits, ill_posed, false);
  const geometry::ConeMargin m = geometry::active_set_margin(r.space, 6);
  r.signed_margin = m.angle;
  r.best_axis = m.direction;
  const bool any_ill_posed = std::any_of(r.limits.begin(), r.limits.end(),
                                         [&](const LimitPlane& l) { return ill_posed(l); });
  const double without =
      any_ill_posed ? geometry::active_set_margin(limit_cone(r.limits, ill_posed, true), 6).angle
                    : r.signed_margin;
  r.rotatable = decide_with_ill_posed(r.signed_margin, without, uncertainty_rad);
  if (r.signed_margin >= -geometry::kAngleEpsRad) r.extreme_rays = r.space.edges(m.angle);

  // Sliding rotation about the block-side normal of each joint through R.
  // One pass over the limit planes gives the margin with and without the
  // ill-posed ones (the min of the sines, then one asin: asin is monotone).
  std::vector<char> parallel(in.planes.size());
  for (int j : topology.vertex_planes[vertex]) {
    if (!in.planes[j].joint) continue;
    SlidingRotation s;
    s.plane = j;
    const Eigen::Vector3d& nj = in.planes[j].inward_normal;
    for (size_t k = 0; k < in.planes.size(); ++k)
      parallel[k] = in.planes[k].inward_normal.cross(nj).norm() < kParallelJointsSin;
    double with_all = 1, well_posed = 1;
    for (const auto& l : r.limits) {
      if (parallel[l.plane]) {
        if (l.plane != j && std::find(s.also_sliding.begin(), s.also_sliding.end(), l.plane) ==
                                s.also_sliding.end())
          s.also_sliding.push_back(l.plane);
        continue;
      }
      const double x = l.normal.dot(nj);
      with_all = std::min(with_all, x);
      if (!ill_posed(l)) well_posed = std::min(well_posed, x);
    }
    s.signed_margin = safe_asin(with_all);
    s.feasible = decide_with_ill_posed(s.signed_margin, safe_asin(well_posed), uncertainty_rad);
    r.sliding.push_back(std::move(s));
  }
  return r;
}

namespace {

// Edge rotation with the limit planes about pivot a already known: those of
// `limits` not on corner b (the other end corner).
EdgeRotation edge_rotation_with(const RotationInput& in, const RotationTopology& topology, int a,
                                int b, const std::vector<LimitPlane>& limits,
                                double uncertainty_rad) {
  EdgeRotation e;
  e.vertices = {std::min(a, b), std::max(a, b)};
  const Eigen::Vector3d pivot = in.vertices[a];
  const Eigen::Vector3d dir = (in.vertices[b] - pivot).normalized();
  // Corners on the axis line (not only its end corners) stay where they are.
  const double on_axis = kOnAxisRel * topology.size;
  const IllPosed ill_posed(uncertainty_rad);
  // One pass: the least sine about +dir is the min of n . dir, about -dir
  // minus its max (negating a vector negates its dot products exactly);
  // with all limit planes and without the ill-posed ones.
  double lo = 1, hi = -1, lo_well = 1, hi_well = -1;
  int last_corner = -1;
  bool on_line = false;
  for (const auto& l : limits) {
    if (l.corner == b) continue;
    if (l.corner != last_corner) {  // a corner's limit planes are consecutive
      last_corner = l.corner;
      const Eigen::Vector3d arm = in.vertices[l.corner] - pivot;
      on_line = !((arm - arm.dot(dir) * dir).norm() > on_axis);
    }
    if (on_line) continue;
    const double x = l.normal.dot(dir);
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    if (!ill_posed(l)) {
      lo_well = std::min(lo_well, x);
      hi_well = std::max(hi_well, x);
    }
  }
  const double plus = safe_asin(lo), minus = safe_asin(-hi);
  e.axis = plus >= minus ? dir : Eigen::Vector3d(-dir);
  e.signed_margin = std::max(plus, minus);
  const double without = std::max(safe_asin(lo_well), safe_asin(-hi_well));
  e.rotatable = decide_with_ill_posed(e.signed_margin, without, uncertainty_rad);
  return e;
}

}  // namespace

EdgeRotation edge_rotation(const RotationInput& in, const RotationTopology& topology, int a, int b,
                           double uncertainty_rad) {
  return edge_rotation_with(in, topology, a, b, limit_planes(in, topology, in.vertices[a], {a, b}),
                            uncertainty_rad);
}

RotationAnalysis analyse_rotation(const RotationInput& in, double uncertainty_rad) {
  const RotationTopology topology = rotation_topology(in);
  RotationAnalysis result;
  for (int v = 0; v < static_cast<int>(in.vertices.size()); ++v)
    if (topology.is_static_point(in, v))
      result.corners.push_back(corner_rotation(in, topology, v, uncertainty_rad));
  // An edge's limit planes about its first corner are that corner's (both
  // ends of a boundary edge are static points) without those of the other
  // corner: the same planes in the same order, not computed again.
  std::vector<int> corner_of(in.vertices.size(), -1);
  for (size_t c = 0; c < result.corners.size(); ++c)
    corner_of[result.corners[c].vertex] = static_cast<int>(c);
  for (const auto& edge : topology.edges) {
    if (!topology.is_boundary_edge(in, edge)) continue;
    const int a = edge.vertices[0], b = edge.vertices[1];
    if (corner_of[a] < 0) {
      result.edges.push_back(edge_rotation(in, topology, a, b, uncertainty_rad));
      continue;
    }
    result.edges.push_back(edge_rotation_with(
        in, topology, a, b, result.corners[corner_of[a]].limits, uncertainty_rad));
  }
  return result;
}

std::optional<FirmAxis> firm_corner_or_edge_axis(const RotationAnalysis& rotation) {
  for (const auto& c : rotation.corners)
    if (c.rotatable.value && !c.rotatable.marginal)
      return FirmAxis{true, c.vertex, {c.vertex, -1}, c.best_axis};
  for (const auto& e : rotation.edges)
    if (e.rotatable.value && !e.rotatable.marginal)
      return FirmAxis{false, e.vertices[0], e.vertices, e.axis};
  return std::nullopt;
}

}  // namespace rockface::kinematics
