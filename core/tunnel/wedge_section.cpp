#include "core/tunnel/wedge_section.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/tunnel/tolerances.h"

namespace rockface::tunnel {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Andrew's monotone chain over the vertices, keeping their attributes;
// collinear points are dropped (they bound no wedge face of their own).
std::vector<SectionVertex> convex_hull(std::vector<SectionVertex> pts) {
  std::sort(pts.begin(), pts.end(), [](const SectionVertex& a, const SectionVertex& b) {
    return a.p.x() < b.p.x() || (a.p.x() == b.p.x() && a.p.y() < b.p.y());
  });
  std::vector<SectionVertex> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 1].p - h[k - 2].p, pts[i].p - h[k - 2].p) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 1].p - h[k - 2].p, pts[i].p - h[k - 2].p) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace

Eigen::Vector2d SectionPolygon::outward_normal(std::size_t i) const {
  const Eigen::Vector2d d = (at(i + 1) - at(i)).normalized();
  return {d.y(), -d.x()};  // counter-clockwise chain: outward is to the right
}

bool SectionPolygon::contains(const Eigen::Vector2d& q) const {
  for (std::size_t i = 0; i < size(); ++i)
    if (outward_normal(i).dot(q - at(i)) > 0) return false;
  return true;
}

double SectionPolygon::distance(const Eigen::Vector2d& q) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < size(); ++i) {
    const Eigen::Vector2d a = at(i), d = at(i + 1) - a;
    const double t = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * d - q).norm());
  }
  return contains(q) ? 0.0 : best;
}

SectionPolygon section_polygon(const DesignProfile& profile, double sagitta_m,
                               const std::string& where) {
  profile.require_valid(where);
  if (!(sagitta_m > 0)) throw InputError(where, "the chords' sagitta must be positive");
  SectionPolygon out;
  const auto& segs = profile.segments();
  std::vector<SectionVertex> pts;
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const ProfileSegment& g = segs[k];
    out.segment_kinds.push_back(g.kind == ProfileSegment::Kind::arc ? "arc" : "line");
    int n = 1;
    if (g.kind == ProfileSegment::Kind::arc) {
      const double r = g.radius();
      const double step = 2 * std::acos(std::max(-1.0, 1 - std::min(sagitta_m, r) / r));
      n = std::max(1, static_cast<int>(std::ceil(std::abs(g.sweep()) / step)));
    }
    const double len = g.length();
    for (int i = 0; i < n; ++i) {
      SectionVertex v;
      v.p = g.point_at(len * i / n);
      v.segment = k;
      if (i == 0) {
        // The turn from the previous segment's end to this one's start.
        const ProfileSegment& prev = segs[(k + segs.size() - 1) % segs.size()];
        const Eigen::Vector2d a = prev.direction_at(prev.length()), b = g.direction_at(0);
        v.corner = std::abs(std::atan2(cross(a, b), a.dot(b))) > kWedgeCornerRad;
      }
      pts.push_back(v);
    }
  }
  // Convex? Every turn to the left (counter-clockwise chain).
  bool convex = true;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& a = pts[i].p;
    const auto& b = pts[(i + 1) % pts.size()].p;
    const auto& c = pts[(i + 2) % pts.size()].p;
    if (cross(b - a, c - b) < -1e-12 * (b - a).norm() * (c - b).norm()) convex = false;
  }
  if (!convex) {
    pts = convex_hull(pts);
    out.hull_used = true;
    out.notes.push_back(
        "the profile is not convex: wedges are formed on its convex hull (a re-entrant part of "
        "the outline is bridged, as rock there cannot fall into the opening on its own)");
  }
  // Drop collinear vertices (a line drawn in pieces) unless they are corners.
  std::vector<SectionVertex> kept;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& a = pts[(i + pts.size() - 1) % pts.size()].p;
    const auto& b = pts[i].p;
    const auto& c = pts[(i + 1) % pts.size()].p;
    if (std::abs(cross(b - a, c - b)) <= 1e-12 * (b - a).norm() * (c - b).norm() &&
        pts[i].segment == pts[(i + pts.size() - 1) % pts.size()].segment)
      continue;
    kept.push_back(pts[i]);
  }
  out.vertices = std::move(kept);
  if (out.vertices.size() < 3) throw InputError(where, "the profile encloses no area");
  double s = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    out.vertices[i].s = s;
    s += (out.at(i + 1) - out.at(i)).norm();
  }
  out.perimeter = s;
  return out;
}

}  // namespace rockface::tunnel
