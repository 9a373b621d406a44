#include "core/geometry/parallel_planes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "core/geometry/tolerances.h"

namespace rockface::geometry {

namespace {

double min_dot_unskipped(const std::vector<Eigen::Vector3d>& normals, const std::vector<bool>& skip,
                         const Eigen::Vector3d& d) {
  double m = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < normals.size(); ++k)
    if (!skip[k]) m = std::min(m, normals[k].dot(d));
  return m;
}

ConeMargin from_sine(double sine, const Eigen::Vector3d& d) {
  ConeMargin c;
  c.sine = std::clamp(sine, -1.0, 1.0);
  c.angle = std::asin(c.sine);
  c.direction = d;
  return c;
}

}  // namespace

std::vector<std::pair<int, int>> opposite_pairs(const std::vector<Eigen::Vector3d>& normals,
                                                double tolerance) {
  std::vector<std::pair<int, int>> out;
  const double cos_tol = std::cos(tolerance);
  for (size_t i = 0; i < normals.size(); ++i)
    for (size_t j = i + 1; j < normals.size(); ++j)
      if (-normals[i].normalized().dot(normals[j].normalized()) >= cos_tol)
        out.emplace_back(static_cast<int>(i), static_cast<int>(j));
  return out;
}

ParallelReduction parallel_reduction(const std::vector<Eigen::Vector3d>& normals,
                                     const std::vector<std::pair<int, int>>& pairs,
                                     double tolerance) {
  ParallelReduction r;
  r.member.assign(normals.size(), false);
  const double cos_tol = std::cos(tolerance);
  for (const auto& [i, j] : pairs) {
    const Eigen::Vector3d a = normals[i].normalized(), b = normals[j].normalized();
    // The bisecting plane's normal: a less b, not a alone, so that the pair
    // is taken through the middle whichever of the two is listed first.
    const Eigen::Vector3d axis = (a - b).normalized();
    r.widest = std::max(r.widest, std::acos(std::clamp(-a.dot(b), -1.0, 1.0)));
    const bool known = std::any_of(r.axes.begin(), r.axes.end(), [&](const Eigen::Vector3d& x) {
      return std::abs(x.dot(axis)) >= cos_tol;
    });
    if (!known) r.axes.push_back(axis);
  }
  for (size_t k = 0; k < normals.size(); ++k)
    for (const auto& x : r.axes)
      if (std::abs(x.dot(normals[k].normalized())) >= cos_tol) r.member[k] = true;
  return r;
}

ConeMargin margin_with_parallel_planes(const std::vector<Eigen::Vector3d>& raw_normals,
                                       const ParallelReduction& reduction) {
  std::vector<Eigen::Vector3d> normals;
  for (const auto& n : raw_normals) normals.push_back(n.normalized());
  if (reduction.axes.empty()) return Cone(normals).margin();
  const std::vector<bool>& skip = reduction.member;
  const bool none_other = std::all_of(skip.begin(), skip.end(), [](bool m) { return m; });

  // Two or more groups: the line normal to all their axes, if they share one.
  if (reduction.axes.size() >= 2) {
    Eigen::Vector3d line = Eigen::Vector3d::Zero();
    for (size_t a = 0; a < reduction.axes.size() && line.isZero(); ++a)
      for (size_t b = a + 1; b < reduction.axes.size(); ++b) {
        const Eigen::Vector3d c = reduction.axes[a].cross(reduction.axes[b]);
        if (c.norm() > kParallelCross) {
          line = c.normalized();
          break;
        }
      }
    for (const auto& x : reduction.axes)
      if (std::abs(x.dot(line)) > kAngleEpsRad) line.setZero();
    // No line lies in every group's plane: the cone is the origin alone,
    // shut, and the ordinary margin says by how much.
    if (line.isZero()) return Cone(normals).margin();
    if (none_other) return from_sine(1, line);
    const double up = min_dot_unskipped(normals, skip, line),
                 down = min_dot_unskipped(normals, skip, -line);
    return up >= down ? from_sine(up, line) : from_sine(down, -line);
  }

  // One group: the plane normal to its axis. The max-min over the circle of
  // its directions lies where one half-space is best (its normal projected
  // into the plane) or where two are equally tight (the plane's directions
  // normal to their difference): all such candidates are evaluated.
  const Eigen::Vector3d axis = reduction.axes.front();
  if (none_other) return from_sine(1, axis.unitOrthogonal());
  const auto in_plane = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(v - v.dot(axis) * axis);
  };
  double best = -std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_d = axis.unitOrthogonal();
  const auto consider = [&](const Eigen::Vector3d& raw) {
    const double len = raw.norm();
    if (!(len > kParallelCross)) return;
    const Eigen::Vector3d d = raw / len;
    const double m = min_dot_unskipped(normals, skip, d);
    if (m > best) {
      best = m;
      best_d = d;
    }
  };
  for (size_t k = 0; k < normals.size(); ++k) {
    if (skip[k]) continue;
    consider(in_plane(normals[k]));
    for (size_t l = k + 1; l < normals.size(); ++l) {
      if (skip[l]) continue;
      const Eigen::Vector3d across = axis.cross(normals[k] - normals[l]);
      consider(across);
      consider(-across);
    }
  }
  if (!std::isfinite(best)) best = min_dot_unskipped(normals, skip, best_d);
  return from_sine(best, best_d);
}

}  // namespace rockface::geometry
