#include "core/tunnel/alignment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/tunnel/survey_ranges.h"
#include "core/tunnel/tolerances.h"

namespace rockface::tunnel {

namespace {

std::string station_name(std::size_t i, double chainage) {
  return "stations[" + std::to_string(i) + "] (chainage " + format_significant(chainage, 10) + ")";
}

// d(x, y, z)/d(chainage) of an element, in the table's direction: the
// horizontal part has length (element length / chainage difference) ~ 1.
Eigen::Vector3d derivative(const Alignment::Element& e, double chainage) {
  const double dc = e.c1 - e.c0;
  const double dz = (e.z1 - e.z0) / dc;
  if (e.radius == 0) {
    const Eigen::Vector2d d = (e.b - e.a) / dc;
    return {d.x(), d.y(), dz};
  }
  const double r = std::abs(e.radius);
  const double rate = e.sweep / dc;  // radians per metre of chainage
  const double theta = e.start_angle + (chainage - e.c0) * rate;
  return {-r * std::sin(theta) * rate, r * std::cos(theta) * rate, dz};
}

// Second derivative (only the arc's horizontal turning; the grade is linear).
Eigen::Vector3d second_derivative(const Alignment::Element& e, double chainage) {
  if (e.radius == 0) return Eigen::Vector3d::Zero();
  const double r = std::abs(e.radius);
  const double rate = e.sweep / (e.c1 - e.c0);
  const double theta = e.start_angle + (chainage - e.c0) * rate;
  return {-r * std::cos(theta) * rate * rate, -r * std::sin(theta) * rate * rate, 0};
}

}  // namespace

const char* drive_name(Drive drive) {
  return drive == Drive::ascending ? "ascending" : "descending";
}

Drive drive_of(const std::string& text, const std::string& where) {
  if (text == "ascending") return Drive::ascending;
  if (text == "descending") return Drive::descending;
  throw InputError(where,
                   "the drive is 'ascending' or 'descending' (chainage), not '" + text + "'");
}

double AlignmentPlace::distance() const {
  return std::hypot(offset, height);
}

Alignment Alignment::from_elements(const std::vector<AlignmentStation>& stations,
                                   const std::vector<double>& radii, const Eigen::Vector3d& datum,
                                   Drive drive) {
  return build(stations, radii, datum, drive, false);
}

Alignment Alignment::from_polyline(const std::vector<AlignmentStation>& stations,
                                   const Eigen::Vector3d& datum, Drive drive) {
  return build(stations, std::vector<double>(stations.empty() ? 0 : stations.size() - 1, 0.0),
               datum, drive, true);
}

Alignment Alignment::build(const std::vector<AlignmentStation>& stations,
                           const std::vector<double>& radii, const Eigen::Vector3d& datum,
                           Drive drive, bool polyline) {
  if (stations.size() < 2)
    throw InputError("stations", "an alignment needs at least two stations, got " +
                                     std::to_string(stations.size()));
  if (radii.size() != stations.size() - 1)
    throw InputError("radii", "one radius per element (" + std::to_string(stations.size() - 1) +
                                  "), got " + std::to_string(radii.size()));
  if (!datum.allFinite()) throw InputError("datum", "must be finite coordinates");
  auto survey_range = [](const Eigen::Vector3d& v) {
    return std::abs(v.x()) <= kMaxSurveyHorizontalM && std::abs(v.y()) <= kMaxSurveyHorizontalM &&
           std::abs(v.z()) <= kMaxSurveyElevationM;
  };
  const std::string ranges =
      "easting and northing within +-" + format_significant(kMaxSurveyHorizontalM, 6) +
      " m, elevation within +-" + format_significant(kMaxSurveyElevationM, 6) + " m";
  if (!survey_range(datum))
    throw InputError("datum", "must be survey coordinates (" + ranges + ")");
  for (std::size_t i = 0; i < stations.size(); ++i) {
    const auto& s = stations[i];
    if (!std::isfinite(s.chainage))
      throw InputError("stations[" + std::to_string(i) + "].chainage", "must be a finite number");
    if (!(std::abs(s.chainage) <= kMaxSurveyHorizontalM))
      throw InputError("stations[" + std::to_string(i) + "].chainage",
                       format_significant(s.chainage, 6) + " is outside +-" +
                           format_significant(kMaxSurveyHorizontalM, 6) + " m");
    if (!s.survey.allFinite())
      throw InputError(station_name(i, s.chainage),
                       "easting, northing and elevation must be finite");
    if (!survey_range(s.survey))
      throw InputError(
          station_name(i, s.chainage),
          "easting, northing and elevation must be survey coordinates (" + ranges + ")");
    if (i > 0) {
      const double prev = stations[i - 1].chainage;
      if (s.chainage == prev)
        throw InputError(station_name(i, s.chainage),
                         "duplicate chainage: the same as " + station_name(i - 1, prev));
      if (s.chainage < prev)
        throw InputError(
            station_name(i, s.chainage),
            "stations must be in ascending chainage; the one before has " + std::to_string(prev));
    }
  }
  Alignment al;
  al.stations_ = stations;
  al.radii_ = radii;
  al.datum_ = datum;
  al.drive_ = drive;
  al.polyline_ = polyline;
  for (std::size_t i = 0; i + 1 < stations.size(); ++i) {
    const Eigen::Vector3d A = stations[i].survey - datum;
    const Eigen::Vector3d B = stations[i + 1].survey - datum;
    Element e;
    e.c0 = stations[i].chainage;
    e.c1 = stations[i + 1].chainage;
    e.a = A.head<2>();
    e.b = B.head<2>();
    e.z0 = A.z();
    e.z1 = B.z();
    e.radius = radii[i];
    const std::string where =
        "element from " + station_name(i, e.c0) + " to " + station_name(i + 1, e.c1);
    if (!std::isfinite(e.radius)) throw InputError(where, "the radius must be a finite number");
    const double chord = (e.b - e.a).norm();
    if (chord < kSamePointM)
      throw InputError(where,
                       "zero-length element: both stations lie at the same easting and "
                       "northing");
    double length = chord;
    if (e.radius != 0) {
      const double r = std::abs(e.radius);
      if (r < chord / 2)
        throw InputError(where, "the radius " + format_significant(e.radius, 6, " m") +
                                    " is smaller than half the chord between the stations (" +
                                    format_significant(chord / 2, 6, " m") +
                                    "): no arc of that radius joins them");
      const double half = std::asin(std::min(1.0, chord / (2 * r)));
      const Eigen::Vector2d d = (e.b - e.a) / chord;
      const Eigen::Vector2d right(d.y(), -d.x());
      const double h = std::sqrt(std::max(0.0, r * r - chord * chord / 4));
      const Eigen::Vector2d mid = (e.a + e.b) / 2;
      // A right turn (clockwise) has its centre to the right of the chord.
      e.centre = e.radius > 0 ? Eigen::Vector2d(mid + h * right) : Eigen::Vector2d(mid - h * right);
      e.start_angle = std::atan2(e.a.y() - e.centre.y(), e.a.x() - e.centre.x());
      e.sweep = e.radius > 0 ? -2 * half : 2 * half;
      length = 2 * half * r;
    }
    const double dc = e.c1 - e.c0;
    if (polyline) {
      if (std::abs(length - dc) > kPolylineMismatchRelative * dc + kChainageMismatchM)
        throw InputError(where, "the chainage advances " + format_significant(dc, 6, " m") +
                                    " but the stations are " + format_significant(length, 6, " m") +
                                    " apart: a wrong chainage or coordinate?");
    } else if (std::abs(length - dc) > kChainageMismatchM + kChainageMismatchRelative * length) {
      throw InputError(where,
                       "the chainage advances " + format_significant(dc, 6, " m") + " but the " +
                           (e.radius == 0 ? std::string("line") : std::string("arc")) +
                           " between the stations is " + format_significant(length, 6, " m") +
                           " long: a wrong chainage, coordinate or radius?");
    }
    al.elements_.push_back(e);
  }
  al.build_bounds();
  return al;
}

void Alignment::build_bounds() {
  mid_.clear();
  reach_.clear();
  for (const Element& e : elements_) {
    mid_.push_back(point_on(e, 0.5 * (e.c0 + e.c1)));
    // The speed |P'(c)| is constant along an element (a line or a circle
    // at a constant grade): every point lies within half the 3D length of
    // the middle one along the element, so within that straight.
    reach_.push_back(0.5 * derivative(e, e.c0).norm() * (e.c1 - e.c0));
  }
  bounds_.clear();
  if (!elements_.empty()) build_bound(0, elements_.size());
}

int Alignment::build_bound(std::size_t first, std::size_t last) {
  const int index = static_cast<int>(bounds_.size());
  bounds_.emplace_back();
  Bound b;
  b.first = first;
  b.last = last;
  for (std::size_t i = first; i < last; ++i) b.centre += mid_[i];
  b.centre /= static_cast<double>(last - first);
  for (std::size_t i = first; i < last; ++i)
    b.radius = std::max(b.radius, (mid_[i] - b.centre).norm() + reach_[i]);
  if (last - first > kAlignmentBoundLeaf) {
    const std::size_t half = first + (last - first) / 2;
    b.left = build_bound(first, half);
    b.right = build_bound(half, last);
  }
  bounds_[index] = b;
  return index;
}

std::pair<double, double> Alignment::foot_on(const Element& e, const Eigen::Vector3d& p) const {
  double c;
  if (e.radius == 0) {
    const Eigen::Vector3d P0 = point_on(e, e.c0);
    const Eigen::Vector3d V = derivative(e, e.c0);
    c = e.c0 + (p - P0).dot(V) / V.squaredNorm();
  } else {
    // Start from the horizontal foot (the polar angle of p about the
    // centre), then Newton on g(c) = (p - P(c)) . P'(c) for the grade.
    const Eigen::Vector2d q = p.head<2>() - e.centre;
    const Eigen::Vector2d a = e.a - e.centre;
    const double turned = std::atan2(a.x() * q.y() - a.y() * q.x(), a.dot(q));
    double f = q.norm() > 0 ? turned / e.sweep : 0.5;
    c = e.c0 + std::clamp(f, -0.5, 1.5) * (e.c1 - e.c0);
    for (int it = 0; it < 30; ++it) {
      const Eigen::Vector3d P = point_on(e, c);
      const Eigen::Vector3d V = derivative(e, c);
      const double g = (p - P).dot(V);
      const double dg = -V.squaredNorm() + (p - P).dot(second_derivative(e, c));
      if (dg >= 0) break;  // not a minimum of the distance here: keep the horizontal foot
      const double step = -g / dg;
      c += step;
      if (std::abs(step) < kFootChainageM) break;
    }
  }
  c = std::clamp(c, e.c0, e.c1);
  return {c, (p - point_on(e, c)).norm()};
}

double Alignment::nearest_foot(const Eigen::Vector3d& p) const {
  // Branch and bound over the spheres: a sphere whose nearest point lies
  // farther than the best foot so far (beyond rounding) holds no better
  // one. Ties go to the earlier element, as a scan in order gives them.
  double best_c = first_chainage();
  double best_d = std::numeric_limits<double>::infinity();
  std::size_t best_i = elements_.size();
  auto farther = [&](const Eigen::Vector3d& centre, double radius) {
    const double lower = (p - centre).norm() - radius;
    return lower > best_d + kAlignmentBoundSlackRel * (best_d + radius + 1.0);
  };
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Bound& b = bounds_[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (farther(b.centre, b.radius)) continue;
    if (b.left >= 0) {
      // The nearer child first: the best foot shrinks sooner.
      const Bound& l = bounds_[static_cast<std::size_t>(b.left)];
      const Bound& r = bounds_[static_cast<std::size_t>(b.right)];
      const bool left_first = (p - l.centre).norm() - l.radius <= (p - r.centre).norm() - r.radius;
      stack.push_back(left_first ? b.right : b.left);
      stack.push_back(left_first ? b.left : b.right);
      continue;
    }
    for (std::size_t i = b.first; i < b.last; ++i) {
      if (farther(mid_[i], reach_[i])) continue;
      const auto [c, d] = foot_on(elements_[i], p);
      if (d < best_d || (d == best_d && i < best_i)) {
        best_d = d;
        best_c = c;
        best_i = i;
      }
    }
  }
  return best_c;
}

double Alignment::first_chainage() const {
  return elements_.front().c0;
}
double Alignment::last_chainage() const {
  return elements_.back().c1;
}

bool Alignment::contains(double chainage) const {
  return chainage >= first_chainage() && chainage <= last_chainage();
}

std::size_t Alignment::element_at(double chainage) const {
  // The element that starts at or before the chainage (a station belongs to
  // the element it starts; the last station to the last element).
  auto it = std::upper_bound(elements_.begin(), elements_.end(), chainage,
                             [](double c, const Element& e) { return c < e.c0; });
  if (it == elements_.begin()) return 0;
  return std::min<std::size_t>(static_cast<std::size_t>(it - elements_.begin()) - 1,
                               elements_.size() - 1);
}

Eigen::Vector3d Alignment::point_on(const Element& e, double chainage) const {
  const double f = (chainage - e.c0) / (e.c1 - e.c0);
  const double z = e.z0 + f * (e.z1 - e.z0);
  if (e.radius == 0) {
    const Eigen::Vector2d p = e.a + f * (e.b - e.a);
    return {p.x(), p.y(), z};
  }
  const double theta = e.start_angle + f * e.sweep;
  const double r = std::abs(e.radius);
  return {e.centre.x() + r * std::cos(theta), e.centre.y() + r * std::sin(theta), z};
}

Eigen::Vector3d Alignment::ascending_tangent(const Element& e, double chainage) const {
  return derivative(e, chainage).normalized();
}

Eigen::Vector3d Alignment::point_at(double chainage) const {
  if (chainage < first_chainage()) {
    const Element& e = elements_.front();
    return point_on(e, e.c0) + (chainage - e.c0) * derivative(e, e.c0);
  }
  if (chainage > last_chainage()) {
    const Element& e = elements_.back();
    return point_on(e, e.c1) + (chainage - e.c1) * derivative(e, e.c1);
  }
  return point_on(elements_[element_at(chainage)], chainage);
}

Eigen::Vector3d Alignment::tangent_at(double chainage) const {
  const Element& e = elements_[element_at(chainage)];
  const double c = std::clamp(chainage, e.c0, e.c1);
  const Eigen::Vector3d t = ascending_tangent(e, c);
  return drive_ == Drive::ascending ? t : Eigen::Vector3d(-t);
}

TunnelFrame Alignment::frame_at(double chainage) const {
  TunnelFrame f;
  f.chainage = chainage;
  f.origin = point_at(chainage);
  f.along = tangent_at(chainage);
  // Tunnels are never vertical (a shaft is not an alignment of this kind):
  // the horizontal part of a tangent is ~1 / sqrt(1 + grade^2).
  f.right = f.along.cross(Eigen::Vector3d::UnitZ()).normalized();
  f.up = f.right.cross(f.along);
  return f;
}

double Alignment::drive_trend_at(double chainage) const {
  const Eigen::Vector3d t = tangent_at(chainage);
  double a = std::atan2(t.x(), t.y());
  if (a < 0) a += 2 * std::numbers::pi;
  return a;
}

AlignmentPlace Alignment::place(const Eigen::Vector3d& p) const {
  // The foot of the perpendicular from p onto each element (the chainage
  // whose cross-section passes through p), kept within the element; the
  // nearest foot wins. In the wedge outside a corner between two elements no
  // cross-section passes through p: the corner's chainage is taken.
  double best_c = nearest_foot(p);
  AlignmentPlace place;
  // Beyond an end: the foot on the end's tangent line, flagged.
  if (best_c == first_chainage()) {
    const Element& e = elements_.front();
    const Eigen::Vector3d V = derivative(e, e.c0);
    const double c = e.c0 + (p - point_on(e, e.c0)).dot(V) / V.squaredNorm();
    if (c < e.c0) {
      best_c = c;
      place.beyond_range = e.c0 - c;
    }
  } else if (best_c == last_chainage()) {
    const Element& e = elements_.back();
    const Eigen::Vector3d V = derivative(e, e.c1);
    const double c = e.c1 + (p - point_on(e, e.c1)).dot(V) / V.squaredNorm();
    if (c > e.c1) {
      best_c = c;
      place.beyond_range = c - e.c1;
    }
  }
  const TunnelFrame f = frame_at(best_c);
  place.chainage = best_c;
  place.offset = (p - f.origin).dot(f.right);
  place.height = (p - f.origin).dot(f.up);
  return place;
}

}  // namespace rockface::tunnel
