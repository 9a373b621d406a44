#include "core/tunnel/design_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/geometry/cross2.h"
#include "core/tunnel/tolerances.h"

namespace rockface::tunnel {

using geometry::cross2;

namespace {

std::string point_text(const Eigen::Vector2d& p) {
  // Appended, not "(" + ...: GCC 12's -Wrestrict misfires on that form.
  std::string text = "(";
  text += format_significant(p.x(), 6);
  text += ", ";
  text += format_significant(p.y(), 6);
  return text + ")";
}

ProfileSegment reversed(const ProfileSegment& s) {
  ProfileSegment r = s;
  std::swap(r.from, r.to);
  r.ccw = !s.ccw;
  return r;
}

// The outline as a closed polygon of chords (arcs split until their sagitta
// is below kProfileSagittaM); edge k runs from points[k] to points[k + 1]
// (the last back to the first) and belongs to segment seg_of[k].
struct Polygon {
  std::vector<Eigen::Vector2d> points;
  std::vector<std::size_t> seg_of;
};

Polygon polygon_of(const std::vector<ProfileSegment>& segments, double sagitta) {
  Polygon poly;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const ProfileSegment& s = segments[i];
    int n = 1;
    if (s.kind == ProfileSegment::Kind::arc) {
      const double r = s.radius();
      // Sagitta of a chord spanning angle a: r (1 - cos(a / 2)).
      const double max_angle = 2 * std::acos(std::max(-1.0, 1 - sagitta / std::max(r, 1e-12)));
      n = std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep()) / max_angle)));
      n = std::min(n, 100000);
    }
    const double len = s.length();
    for (int k = 0; k < n; ++k) {
      poly.points.push_back(s.point_at(len * k / n));
      poly.seg_of.push_back(i);
    }
  }
  return poly;
}

bool segments_cross(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& q1,
                    const Eigen::Vector2d& q2) {
  const double d1 = cross2(p2 - p1, q1 - p1), d2 = cross2(p2 - p1, q2 - p1);
  const double d3 = cross2(q2 - q1, p1 - q1), d4 = cross2(q2 - q1, p2 - q1);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  // Touching (an end on the other segment) counts: the outline would pinch.
  auto on = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p,
               double d) {
    return std::abs(d) <= 1e-12 * std::max(1.0, (b - a).squaredNorm()) &&
           p.x() >= std::min(a.x(), b.x()) - 1e-12 && p.x() <= std::max(a.x(), b.x()) + 1e-12 &&
           p.y() >= std::min(a.y(), b.y()) - 1e-12 && p.y() <= std::max(a.y(), b.y()) + 1e-12;
  };
  return on(p1, p2, q1, d1) || on(p1, p2, q2, d2) || on(q1, q2, p1, d3) || on(q1, q2, p2, d4);
}

}  // namespace

// ---------------------------------------------------------------- segments

ProfileSegment ProfileSegment::line(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  ProfileSegment s;
  s.kind = Kind::line;
  s.from = from;
  s.to = to;
  return s;
}

ProfileSegment ProfileSegment::arc(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                   const Eigen::Vector2d& centre, bool ccw) {
  ProfileSegment s;
  s.kind = Kind::arc;
  s.from = from;
  s.to = to;
  s.centre = centre;
  s.ccw = ccw;
  return s;
}

ProfileSegment ProfileSegment::arc_polar(const Eigen::Vector2d& centre, double radius,
                                         double start_angle, double end_angle) {
  ProfileSegment s =
      arc(centre + radius * Eigen::Vector2d(std::cos(start_angle), std::sin(start_angle)),
          centre + radius * Eigen::Vector2d(std::cos(end_angle), std::sin(end_angle)), centre,
          end_angle > start_angle);
  return s;
}

double ProfileSegment::sweep() const {
  if (kind == Kind::line) return 0;
  // from == to (within the join tolerance) is a full circle.
  if ((to - from).norm() <= kProfileJoinM) return ccw ? 2 * kPi : -2 * kPi;
  // The angle between the radii from the chord (to - from), not as the
  // difference of the radii's polar angles: those carry ~1e-16 rad of
  // rounding each, which a nearly straight arc (radius 1e9 m over 6 m,
  // a sweep of 6e-9 rad) turned into 1e-8 of its sweep and 26 m^2 of a
  // 30 m^2 profile's area (issue 40).
  const Eigen::Vector2d r0 = from - centre, chord = to - from;
  double d = std::atan2(cross2(r0, chord), r0.squaredNorm() + r0.dot(chord));
  if (ccw) {
    while (d <= 0) d += 2 * kPi;
    while (d > 2 * kPi) d -= 2 * kPi;
  } else {
    while (d >= 0) d -= 2 * kPi;
    while (d < -2 * kPi) d += 2 * kPi;
  }
  return d;
}

double ProfileSegment::length() const {
  if (kind == Kind::line) return (to - from).norm();
  return radius() * std::abs(sweep());
}

Eigen::Vector2d ProfileSegment::point_at(double t) const {
  if (kind == Kind::line) {
    const double len = length();
    return len > 0 ? Eigen::Vector2d(from + (to - from) * (t / len)) : from;
  }
  const double r = radius();
  const double a =
      std::atan2(from.y() - centre.y(), from.x() - centre.x()) + (sweep() > 0 ? 1.0 : -1.0) * t / r;
  return centre + r * Eigen::Vector2d(std::cos(a), std::sin(a));
}

Eigen::Vector2d ProfileSegment::direction_at(double t) const {
  if (kind == Kind::line) return (to - from).normalized();
  const Eigen::Vector2d radial = (point_at(t) - centre).normalized();
  return sweep() > 0 ? Eigen::Vector2d(-radial.y(), radial.x())
                     : Eigen::Vector2d(radial.y(), -radial.x());
}

// ---------------------------------------------------------------- profile

namespace {

// t - sin t without the cancellation of its two terms for small t: below
// 0.1 rad by its series (the first omitted term, t^11 / 11!, is under
// 1e-18 of t^3 / 6 there).
double angle_less_sine(double t) {
  if (std::abs(t) >= 0.1) return t - std::sin(t);
  const double t2 = t * t;
  return t * t2 * (1.0 / 6 - t2 * (1.0 / 120 - t2 * (1.0 / 5040 - t2 / 362880)));
}

// Twice the signed area swept by one segment about the origin (Green):
// lines x dy - y dx; an arc its chord's term plus its circular segment,
// r^2 (t - sin t), exactly. (Written as the centre's term plus r^2 t, the
// two cancel for a nearly straight arc: at a radius of 1e9 m each is
// 1e10 m^2 for a segment of 1e-8 m^2.)
double twice_area_term(const ProfileSegment& s) {
  double a = cross2(s.from, s.to);
  if (s.kind == ProfileSegment::Kind::arc) {
    const double r = s.radius();
    a += r * r * angle_less_sine(s.sweep());
  }
  return a;
}

}  // namespace

DesignProfile::DesignProfile(std::vector<ProfileSegment> segments,
                             std::optional<Eigen::Vector2d> ray_centre, std::string name)
    : segments_(std::move(segments)), name_(std::move(name)) {
  double twice = 0;
  for (const auto& s : segments_) twice += twice_area_term(s);
  if (twice < 0) {
    std::vector<ProfileSegment> r;
    for (auto it = segments_.rbegin(); it != segments_.rend(); ++it) r.push_back(reversed(*it));
    segments_ = std::move(r);
  }
  start_s_.assign(segments_.size() + 1, 0.0);
  for (std::size_t i = 0; i < segments_.size(); ++i)
    start_s_[i + 1] = start_s_[i] + segments_[i].length();
  ray_centre_given_ = ray_centre.has_value();
  ray_centre_ = ray_centre ? *ray_centre : centroid();
}

double DesignProfile::perimeter() const {
  return start_s_.empty() ? 0 : start_s_.back();
}

double DesignProfile::area() const {
  double twice = 0;
  for (const auto& s : segments_) twice += twice_area_term(s);
  return std::abs(twice) / 2;
}

Eigen::Vector2d DesignProfile::centroid() const {
  // Of the polygon of fine chords (sagitta 1e-6 m: the centroid is off by
  // less than that).
  if (segments_.empty()) return Eigen::Vector2d::Zero();
  const Polygon poly = polygon_of(segments_, 1e-6);
  double a = 0;
  Eigen::Vector2d c(0, 0);
  const auto& p = poly.points;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& p0 = p[k];
    const auto& p1 = p[(k + 1) % p.size()];
    const double w = cross2(p0, p1);
    a += w;
    c += w * (p0 + p1);
  }
  if (std::abs(a) < 1e-300) return p.front();
  return c / (3 * a);
}

ProfileCheck DesignProfile::validate() const {
  auto bad = [](std::string message, std::optional<std::size_t> seg) {
    return ProfileCheck{false, std::move(message), seg};
  };
  if (segments_.empty()) return bad("the profile has no segments", std::nullopt);
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const auto& s = segments_[i];
    if (!s.from.allFinite() || !s.to.allFinite() ||
        (s.kind == ProfileSegment::Kind::arc && !s.centre.allFinite()))
      return bad("coordinates must be finite numbers", i);
    if (s.kind == ProfileSegment::Kind::arc) {
      const double r0 = (s.from - s.centre).norm(), r1 = (s.to - s.centre).norm();
      if (r0 <= kProfileJoinM) return bad("the arc's centre lies on its start point", i);
      if (std::abs(r0 - r1) > kProfileJoinM)
        return bad("the arc's ends are not on one circle about its centre (radius " +
                       std::to_string(r0) + " m at its start, " + std::to_string(r1) +
                       " m at its end)",
                   i);
    }
    if (s.length() <= kProfileSegmentMinM) return bad("the segment has no length", i);
    const auto& next = segments_[(i + 1) % segments_.size()];
    if ((s.to - next.from).norm() > kProfileJoinM)
      return bad("the chain is not closed: the segment ends at " + point_text(s.to) +
                     " but the next starts at " + point_text(next.from),
                 i);
  }
  if (area() <= kProfileJoinM * kProfileJoinM)
    return bad("the profile encloses no area", std::nullopt);
  const Polygon poly = polygon_of(segments_, kProfileSagittaM);
  const auto& p = poly.points;
  const std::size_t n = p.size();
  // Star shape: seen from the ray centre the outline turns strictly
  // counter-clockwise, once round (then every ray meets it once). Such an
  // outline cannot cross itself (its chords lie in disjoint sectors about
  // the centre), so the pairwise crossing test, quadratic in the chords,
  // runs only for an outline that is not star-shaped, to say where it
  // crosses itself when it does (issue 41: 100 000 segments took minutes).
  std::optional<ProfileCheck> not_star;
  double turned = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d a = p[k] - ray_centre_, b = p[(k + 1) % n] - ray_centre_;
    const double c = cross2(a, b);
    if (c <= 0) {
      not_star = bad("the outline is not star-shaped from the ray centre " +
                         point_text(ray_centre_) + ": the ray toward " + point_text(p[k]) +
                         " meets it more than once or runs along it; give a ray centre that "
                         "sees the whole outline",
                     poly.seg_of[k]);
      break;
    }
    turned += std::atan2(c, a.dot(b));
  }
  if (!not_star && std::abs(turned - 2 * kPi) > 1e-6)
    not_star = bad("the ray centre " + point_text(ray_centre_) + " lies outside the profile",
                   std::nullopt);
  if (!not_star) return {};
  if (n <= kProfileCrossingCheckChords)
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;  // adjacent across the start
        if (segments_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) {
          return bad("the outline crosses itself near " + point_text(p[j]) + " (segments " +
                         std::to_string(poly.seg_of[i]) + " and " + std::to_string(poly.seg_of[j]) +
                         ")",
                     poly.seg_of[j]);
        }
      }
    }
  return *not_star;
}

void DesignProfile::require_valid(const std::string& where) const {
  const ProfileCheck check = validate();
  if (check.ok) return;
  throw InputError(
      check.segment ? where + ".segments[" + std::to_string(*check.segment) + "]" : where,
      check.message);
}

Eigen::Vector2d DesignProfile::point_at_length(double s) const {
  const double P = perimeter();
  s = std::fmod(s, P);
  if (s < 0) s += P;
  auto it = std::upper_bound(start_s_.begin(), start_s_.end(), s);
  std::size_t i = static_cast<std::size_t>(it - start_s_.begin());
  i = std::clamp<std::size_t>(i == 0 ? 0 : i - 1, 0, segments_.size() - 1);
  return segments_[i].point_at(s - start_s_[i]);
}

Eigen::Vector2d DesignProfile::outward_normal_at_length(double s) const {
  const double P = perimeter();
  s = std::fmod(s, P);
  if (s < 0) s += P;
  auto it = std::upper_bound(start_s_.begin(), start_s_.end(), s);
  std::size_t i = static_cast<std::size_t>(it - start_s_.begin());
  i = std::clamp<std::size_t>(i == 0 ? 0 : i - 1, 0, segments_.size() - 1);
  const Eigen::Vector2d d = segments_[i].direction_at(s - start_s_[i]);
  return {d.y(), -d.x()};  // the chain runs counter-clockwise: outward is to its right
}

double DesignProfile::angle_at_length(double s) const {
  const Eigen::Vector2d d = point_at_length(s) - ray_centre_;
  return std::atan2(d.y(), d.x());
}

ProfileHit DesignProfile::ray_hit(double angle) const {
  const Eigen::Vector2d c = ray_centre_;
  const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
  ProfileHit best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const ProfileSegment& s = segments_[i];
    if (s.kind == ProfileSegment::Kind::line) {
      const Eigen::Vector2d e = s.to - s.from;
      const double den = cross2(d, e);
      if (den == 0) continue;
      const Eigen::Vector2d w = s.from - c;
      const double t = cross2(w, e) / den;  // along the ray
      const double u = cross2(w, d) / den;  // along the segment, [0, 1]
      if (t > 0 && u >= 0 && u <= 1 && t < best.distance) {
        best.distance = t;
        best.point = c + t * d;
        best.s = start_s_[i] + u * s.length();
        best.outward_normal = Eigen::Vector2d(e.y(), -e.x()).normalized();
        best.segment = i;
      }
      continue;
    }
    // Arc: |c + t d - centre| = r; both roots, kept when on the arc.
    const double r = s.radius();
    const Eigen::Vector2d w = c - s.centre;
    const double b = w.dot(d), q = w.squaredNorm() - r * r;
    const double disc = b * b - q;
    if (disc < 0) continue;
    const double a0 = std::atan2(s.from.y() - s.centre.y(), s.from.x() - s.centre.x());
    const double sw = s.sweep();
    for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
      if (!(t > 0) || t >= best.distance) continue;
      const Eigen::Vector2d p = c + t * d;
      double rel = std::atan2(p.y() - s.centre.y(), p.x() - s.centre.x()) - a0;
      if (sw > 0) {
        while (rel < 0) rel += 2 * kPi;
        while (rel >= 2 * kPi) rel -= 2 * kPi;
      } else {
        while (rel > 0) rel -= 2 * kPi;
        while (rel <= -2 * kPi) rel += 2 * kPi;
      }
      // Slack of an ulp-scale angle so a ray through a joint is not lost.
      if (std::abs(rel) > std::abs(sw) + 1e-12) continue;
      best.distance = t;
      best.point = p;
      best.s = start_s_[i] + std::abs(rel) * r;
      best.outward_normal = (p - s.centre).normalized() * (sw > 0 ? 1.0 : -1.0);
      best.segment = i;
    }
  }
  return best;
}

// ---------------------------------------------------------------- helpers

DesignProfile circle_profile(double radius, double centre_v) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("radius", "must be positive");
  const Eigen::Vector2d c(0, centre_v);
  const Eigen::Vector2d bottom(0, centre_v - radius), top(0, centre_v + radius);
  return DesignProfile({ProfileSegment::arc(bottom, top, c), ProfileSegment::arc(top, bottom, c)},
                       c, "circle");
}

DesignProfile rectangle_profile(double width, double height, double floor_v) {
  if (!(width > 0)) throw InputError("width", "must be positive");
  if (!(height > 0)) throw InputError("height", "must be positive");
  const double h = width / 2, top = floor_v + height;
  const Eigen::Vector2d a(0, floor_v), b(h, floor_v), c(h, top), d(-h, top), e(-h, floor_v);
  return DesignProfile(
      {ProfileSegment::line(a, b), ProfileSegment::line(b, c), ProfileSegment::line(c, d),
       ProfileSegment::line(d, e), ProfileSegment::line(e, a)},
      Eigen::Vector2d(0, floor_v + height / 2), "rectangle");
}

DesignProfile horseshoe_profile(double crown_radius, double springline_v, double wall_radius,
                                double invert_v) {
  if (!(crown_radius > 0)) throw InputError("crown_radius", "must be positive");
  if (!(wall_radius >= crown_radius))
    throw InputError("wall_radius", "must be at least the crown radius");
  if (!(invert_v < springline_v))
    throw InputError("invert_v", "the invert must lie below the springline");
  const double drop = springline_v - invert_v;
  if (drop >= wall_radius)
    throw InputError("invert_v", "the walls (radius " + std::to_string(wall_radius) +
                                     " m) cannot reach an invert " + std::to_string(drop) +
                                     " m below the springline");
  // Right wall: centre (r - R, hs); it reaches the invert at angle -phi.
  const double phi = std::asin(drop / wall_radius);
  const double half = crown_radius - wall_radius + wall_radius * std::cos(phi);
  if (!(half > kProfileJoinM))
    throw InputError("invert_v", "the walls cross before they reach the invert");
  const Eigen::Vector2d cr(crown_radius - wall_radius, springline_v);
  const Eigen::Vector2d cl(wall_radius - crown_radius, springline_v);
  const Eigen::Vector2d crown_c(0, springline_v);
  const Eigen::Vector2d inv_mid(0, invert_v), inv_r(half, invert_v), inv_l(-half, invert_v);
  const Eigen::Vector2d spring_r(crown_radius, springline_v), spring_l(-crown_radius, springline_v);
  return DesignProfile(
      {ProfileSegment::line(inv_mid, inv_r), ProfileSegment::arc(inv_r, spring_r, cr),
       ProfileSegment::arc(spring_r, spring_l, crown_c), ProfileSegment::arc(spring_l, inv_l, cl),
       ProfileSegment::line(inv_l, inv_mid)},
      crown_c, "horseshoe");
}

}  // namespace rockface::tunnel
