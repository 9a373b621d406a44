#include "core/geometry/stereonet.h"

#include <cmath>
#include <numbers>

namespace rockface::geometry {

Eigen::Vector2d project_direction(const Eigen::Vector3d& d_in, Projection p, Hemisphere h) {
  Eigen::Vector3d d = d_in.normalized();
  // Fold the axis into the hemisphere looked at: lower means d.z <= 0.
  if ((h == Hemisphere::Lower && d.z() > 0) || (h == Hemisphere::Upper && d.z() < 0)) d = -d;
  // Angle from the hemisphere's pole (straight down for the lower one).
  const double horizontal = std::hypot(d.x(), d.y());
  const double theta = std::atan2(horizontal, std::abs(d.z()));
  const double r =
      p == Projection::EqualAngle ? std::tan(theta / 2) : std::sqrt(2.0) * std::sin(theta / 2);
  if (horizontal == 0) return Eigen::Vector2d::Zero();
  // Both hemispheres are plotted seen from above, North up and East right;
  // only the folding of the axis differs.
  return {r * d.x() / horizontal, r * d.y() / horizontal};
}

Eigen::Vector2d project_pole(const PlaneOrientation& plane, Projection p, Hemisphere h) {
  return project_direction(plane_normal(plane), p, h);
}

std::vector<Eigen::Vector2d> project_great_circle(const PlaneOrientation& plane, Projection p,
                                                  Hemisphere h, int samples) {
  const Eigen::Vector3d n = plane_normal(plane);
  // Two orthonormal directions in the plane: the strike line and the dip line.
  Eigen::Vector3d strike = Eigen::Vector3d::UnitZ().cross(n);
  if (strike.norm() < 1e-12)
    strike = Eigen::Vector3d::UnitX();  // horizontal plane: any horizontal line
  strike.normalize();
  Eigen::Vector3d dip_line = n.cross(strike).normalized();
  // Dip line pointing into the hemisphere.
  if ((h == Hemisphere::Lower) == (dip_line.z() > 0)) dip_line = -dip_line;
  std::vector<Eigen::Vector2d> pts;
  pts.reserve(samples);
  for (int i = 0; i < samples; ++i) {
    const double a = std::numbers::pi * i / (samples - 1);
    const Eigen::Vector3d d = std::cos(a) * strike + std::sin(a) * dip_line;
    pts.push_back(project_direction(d, p, h));
  }
  return pts;
}

std::optional<Eigen::Vector3d> direction_at(const Eigen::Vector2d& point, Projection p,
                                            Hemisphere h) {
  const double r = point.norm();
  if (!(r <= 1.0)) return std::nullopt;  // also NaN
  // Invert r(theta) of project_direction.
  const double theta =
      p == Projection::EqualAngle ? 2 * std::atan(r) : 2 * std::asin(r / std::sqrt(2.0));
  const double z = std::cos(theta);
  const double horizontal = std::sin(theta);
  Eigen::Vector3d d(0, 0, h == Hemisphere::Lower ? -z : z);
  if (r > 0) {
    d.x() = horizontal * point.x() / r;
    d.y() = horizontal * point.y() / r;
  }
  return d;
}

}  // namespace rockface::geometry
