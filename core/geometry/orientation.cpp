#include "core/geometry/orientation.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/common/units.h"

namespace rockface::geometry {

double wrap_azimuth(double azimuth) {
  constexpr double two_pi = 2 * std::numbers::pi;
  double a = std::fmod(azimuth, two_pi);
  if (a < 0) a += two_pi;
  // fmod of a value just below a multiple of 2 pi can round up to 2 pi itself.
  if (a >= two_pi) a = 0;
  return a;
}

Eigen::Vector3d plane_normal(const PlaneOrientation& o) {
  const double sa = std::sin(o.dip), ca = std::cos(o.dip);
  return {sa * std::sin(o.dipdir), sa * std::cos(o.dipdir), ca};
}

Eigen::Vector3d plane_normal_deg(double dip_deg, double dipdir_deg) {
  // The same conversion as every caller made by hand before, to the bit.
  return plane_normal({deg_to_rad(dip_deg), deg_to_rad(dipdir_deg)});
}

PlaneOrientation plane_orientation(const Eigen::Vector3d& n_in) {
  Eigen::Vector3d n = n_in.normalized();
  if (n.z() < 0) n = -n;
  const double horizontal = std::hypot(n.x(), n.y());
  PlaneOrientation o;
  // atan2 of (horizontal, vertical) stays accurate near both 0 and 90 degrees,
  // where acos / asin lose half their digits.
  o.dip = std::atan2(horizontal, n.z());
  o.dipdir = horizontal > 0 ? wrap_azimuth(std::atan2(n.x(), n.y())) : 0.0;
  return o;
}

Eigen::Vector3d line_direction(const LineOrientation& o) {
  const double cp = std::cos(o.plunge);
  return {cp * std::sin(o.trend), cp * std::cos(o.trend), -std::sin(o.plunge)};
}

LineOrientation line_orientation(const Eigen::Vector3d& d_in) {
  const Eigen::Vector3d d = d_in.normalized();
  const double horizontal = std::hypot(d.x(), d.y());
  LineOrientation o;
  o.plunge = std::atan2(-d.z(), horizontal);
  o.trend = horizontal > 0 ? wrap_azimuth(std::atan2(d.x(), d.y())) : 0.0;
  return o;
}

}  // namespace rockface::geometry
