#include "camera/tunnel_lighting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.h"

namespace rockface::camera {

using Eigen::Vector2d;
using Eigen::Vector3d;

PreparedRegion::PreparedRegion(const SyntheticRegion& region, const std::string& where) {
  if (region.polygon.size() < 3) throw InputError(where, "a region needs at least 3 points");
  Vector3d n = Vector3d::Zero(), centroid = Vector3d::Zero();
  for (std::size_t i = 0; i < region.polygon.size(); ++i) {
    n += region.polygon[i].cross(region.polygon[(i + 1) % region.polygon.size()]);
    centroid += region.polygon[i];
  }
  if (n.norm() < 1e-9) throw InputError(where, "the polygon has no area");
  normal_ = n.normalized();
  origin_ = centroid / static_cast<double>(region.polygon.size());
  eu_ = (std::abs(normal_.z()) < 0.9 ? Vector3d::UnitZ() : Vector3d::UnitX())
            .cross(normal_)
            .normalized();
  ev_ = normal_.cross(eu_);
  lo_ = Vector2d::Constant(std::numeric_limits<double>::infinity());
  hi_ = -lo_;
  for (const auto& x : region.polygon) {
    polygon_.push_back(local(x));
    lo_ = lo_.cwiseMin(polygon_.back());
    hi_ = hi_.cwiseMax(polygon_.back());
  }
}

Vector2d PreparedRegion::local(const Vector3d& q) const {
  return {(q - origin_).dot(eu_), (q - origin_).dot(ev_)};
}

bool PreparedRegion::contains(const Vector3d& q) const {
  if (std::abs(normal_.dot(q - origin_)) > SyntheticRegion::kRegionReach) return false;
  const Vector2d p = local(q);
  if (p.x() < lo_.x() || p.y() < lo_.y() || p.x() > hi_.x() || p.y() > hi_.y()) return false;
  bool inside = false;
  for (std::size_t i = 0, j = polygon_.size() - 1; i < polygon_.size(); j = i++) {
    const Vector2d& a = polygon_[i];
    const Vector2d& b = polygon_[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

std::vector<std::array<Vector3d, 2>> PreparedRegion::outside(const Vector3d& a,
                                                             const Vector3d& b) const {
  // Where the segment crosses the polygon's edges (in the region's plane),
  // as fractions along it; between two crossings it is wholly in or out.
  const Vector2d pa = local(a), pb = local(b);
  std::vector<double> cuts{0.0, 1.0};
  for (std::size_t i = 0, j = polygon_.size() - 1; i < polygon_.size(); j = i++) {
    const Vector2d e = polygon_[i] - polygon_[j], d = pb - pa;
    const double den = d.x() * e.y() - d.y() * e.x();
    if (std::abs(den) < 1e-15) continue;
    const Vector2d w = polygon_[j] - pa;
    const double s = (w.x() * e.y() - w.y() * e.x()) / den;  // along the segment
    const double u = (w.x() * d.y() - w.y() * d.x()) / den;  // along the edge
    if (s > 0 && s < 1 && u >= 0 && u <= 1) cuts.push_back(s);
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::array<Vector3d, 2>> out;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] - cuts[k] < 1e-12) continue;
    const Vector3d from = a + cuts[k] * (b - a), to = a + cuts[k + 1] * (b - a);
    if (contains(0.5 * (from + to))) continue;
    if (!out.empty() && (out.back()[1] - from).norm() < 1e-12)
      out.back()[1] = to;  // one piece across a cut that was only touched
    else
      out.push_back({from, to});
  }
  return out;
}

TunnelLights::TunnelLights(const SyntheticEffects& effects, const SyntheticStation& station) {
  if (effects.flash) {
    const double d = (station.look_at - station.position).norm();
    lights_.push_back({station.position, effects.flash->intensity * d * d});
  }
  for (const auto& lamp : effects.lamps) lights_.push_back({lamp.position, lamp.intensity});
}

double TunnelLights::diffuse(const Vector3d& q, const Vector3d& n) const {
  double e = 0;
  for (const auto& light : lights_) {
    const Vector3d to_light = light.position - q;
    const double d2 = std::max(to_light.squaredNorm(), 1e-6);
    const double cosine = n.dot(to_light) / std::sqrt(d2);
    if (cosine > 0) e += light.intensity * cosine / d2;
  }
  return e;
}

double TunnelLights::specular(const Vector3d& q, const Vector3d& n, const Vector3d& to_camera,
                              double shininess) const {
  double e = 0;
  for (const auto& light : lights_) {
    const Vector3d to_light = light.position - q;
    const double d2 = std::max(to_light.squaredNorm(), 1e-6);
    const Vector3d l = to_light / std::sqrt(d2);
    if (n.dot(l) <= 0) continue;
    const double nh = n.dot((l + to_camera).normalized());
    if (nh > 0) e += std::pow(nh, shininess) * light.intensity / d2;
  }
  return e;
}

double headlamp_specular(const Vector3d& q, const Vector3d& n, const Vector3d& to_camera,
                         const Vector3d& lamp, double shininess) {
  const Vector3d l = (lamp - q).normalized();
  if (n.dot(l) <= 0) return 0;
  const double nh = n.dot((l + to_camera).normalized());
  return nh > 0 ? std::pow(nh, shininess) : 0.0;
}

}  // namespace rockface::camera
