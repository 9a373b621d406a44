#include "core/faces/trace_plane.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/faces/tolerances.h"
#include "core/geometry/plane_fit.h"

namespace rockface::faces {

namespace {

geometry::Plane upward_plane(Eigen::Vector3d n, double offset_point_dot) {
  (void)offset_point_dot;
  geometry::Plane p;
  if (n.z() < 0 || (n.z() == 0 && (n.y() < 0 || (n.y() == 0 && n.x() < 0)))) n = -n;
  p.normal = n.normalized();
  return p;
}

std::string metres(double v) {
  return format_significant(v, 3, " m");
}

}  // namespace

std::vector<std::vector<int>> points_on_patches(const std::vector<Eigen::Vector3d>& points,
                                                const FreeSurface& surface, double tolerance) {
  std::vector<std::vector<int>> on(points.size());
  const auto& patches = surface.patches();
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t k = 0; k < patches.size(); ++k) {
      const SurfacePatch& p = patches[k];
      if (std::abs(p.height(points[i])) > tolerance) continue;
      if (p.contains(p.to2d(points[i]), tolerance)) on[i].push_back(static_cast<int>(k));
    }
  return on;
}

TracePlaneResult resolve_trace_plane(const TraceInput& trace, const FreeSurface& surface,
                                     const std::vector<int>& patches_touched, double tolerance) {
  TracePlaneResult result;
  const auto& pts = trace.points;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : pts) centroid += p;
  centroid /= static_cast<double>(pts.size());

  if (trace.joint) {
    TracePlane tp;
    tp.plane = upward_plane(geometry::plane_normal(trace.joint->orientation), 0);
    tp.plane.offset = tp.plane.normal.dot(centroid);
    for (const auto& p : pts)
      tp.max_residual = std::max(tp.max_residual, std::abs(tp.plane.signed_distance(p)));
    tp.source = TracePlaneSource::Joint;
    if (tp.max_residual > kGivenPlaneResidualInTolerances * tolerance)
      result.problem = "departs up to " + metres(tp.max_residual) + " from a plane of joint " +
                       trace.joint->id + "'s orientation";
    result.plane = tp;
    return result;
  }

  // Fit. The orientation is determined only by relief off every single patch
  // plane: a trace on one planar patch is a straight line (or, marked by hand,
  // a wobble in the patch plane) and says nothing about the joint's dip.
  std::vector<Eigen::Vector3d> normals;
  for (int k : patches_touched) {
    const Eigen::Vector3d n = surface.patches()[k].outward;
    bool seen = false;
    for (const auto& m : normals) seen = seen || std::abs(n.dot(m)) > std::cos(deg_to_rad(1.0));
    if (!seen) normals.push_back(n);
  }
  if (pts.size() < 3 || normals.size() < 2) {
    result.problem =
        "orientation unknown: no joint given and the trace lies on one plane of the "
        "surface, so its dip cannot be fitted";
    return result;
  }
  const geometry::PlaneFit fit = geometry::fit_plane(pts);
  const double rms_off = fit.rms_off_plane();
  const double relief = fit.relief();
  const double needed = tolerance / std::tan(deg_to_rad(kMaxFitUncertaintyDeg));
  if (relief < needed) {
    result.problem = "orientation unknown: relief " + metres(relief) +
                     " (RMS off its line) is "
                     "below the " +
                     metres(needed) + " a fit needs at this snap tolerance";
    return result;
  }
  if (rms_off > kPlanarityInTolerances * tolerance) {
    result.problem =
        "orientation unknown: not planar (RMS " + metres(rms_off) + " off the best-fit plane)";
    return result;
  }
  TracePlane tp;
  tp.plane = fit.plane();
  for (const auto& p : pts)
    tp.max_residual = std::max(tp.max_residual, std::abs(tp.plane.signed_distance(p)));
  tp.source = TracePlaneSource::Fitted;
  tp.uncertainty = std::atan2(tolerance, relief);
  result.plane = tp;
  return result;
}

}  // namespace rockface::faces
