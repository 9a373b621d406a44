#include "core/tunnel/wedge_section.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

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

// Distance from p to the line through a and b.
double off_line(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double len = d.norm();
  return len > 0 ? std::abs(cross(d, p - a)) / len : (p - a).norm();
}

// A curve drawn as many short lines (a circle as 5000 chords) is merged
// into the chords the wedge search would draw for an arc: a vertex between
// two of the profile's lines where the outline does not turn a corner is
// dropped while every dropped vertex stays within sagitta_m of the chord
// that replaces them. Convex in, convex out (dropping vertices of a convex
// polygon keeps it convex); corners and arcs' chords are kept. Returns how
// many vertices were dropped. (Thousands of millimetre chords gave the
// wedges thousands of sliver pieces that no longer joined, issue 40.)
std::size_t merge_line_chords(std::vector<SectionVertex>& pts,
                              const std::vector<std::string>& kinds, double sagitta_m) {
  const std::size_t n = pts.size();
  if (n < 4) return 0;
  auto line_edge = [&](std::size_t i) { return kinds[pts[i % n].segment] == "line"; };
  std::vector<bool> mergeable(n);
  std::size_t start = n;
  for (std::size_t i = 0; i < n; ++i) {
    // A join where the outline runs straight on (one line drawn as two
    // segments, a horseshoe's invert about its middle) is kept as given:
    // it bounds no sliver, and its segments are the drawing's own.
    const Eigen::Vector2d& a = pts[(i + n - 1) % n].p;
    const Eigen::Vector2d& b = pts[i].p;
    const Eigen::Vector2d& c = pts[(i + 1) % n].p;
    const bool straight_on =
        std::abs(cross(b - a, c - b)) <= 1e-12 * (b - a).norm() * (c - b).norm();
    mergeable[i] = !pts[i].corner && !straight_on && line_edge(i) && line_edge(i + n - 1);
    if (!mergeable[i] && start == n) start = i;
  }
  if (start == n) start = 0;      // a closed run of lines with no corner: start anywhere
  std::vector<std::size_t> kept;  // indices into pts
  std::vector<std::vector<std::pair<double, std::size_t>>> joins(n);
  std::size_t anchor = start, dropped = 0;
  kept.push_back(anchor);
  // Walk once round from the anchor; `end` indexes past it (mod n).
  std::size_t end = anchor + 1;
  while (end < start + n) {
    // Extend the chord from anchor over mergeable vertices while every
    // vertex between stays within the sagitta.
    std::size_t last = end;  // candidate end of the chord
    while (mergeable[last % n] && last + 1 <= start + n) {
      const std::size_t next = last + 1;
      bool within = true;
      for (std::size_t k = anchor + 1; k < next && within; ++k)
        within = off_line(pts[k % n].p, pts[anchor % n].p, pts[next % n].p) <= sagitta_m;
      if (!within) break;
      last = next;
    }
    // The segments the chord now carries, where each begins along it.
    const Eigen::Vector2d a = pts[anchor % n].p, d = pts[last % n].p - a;
    for (std::size_t k = anchor + 1; k < last; ++k)
      if (pts[k % n].segment != pts[(k - 1) % n].segment)
        joins[anchor % n].emplace_back((pts[k % n].p - a).dot(d) / d.squaredNorm(),
                                       pts[k % n].segment);
    dropped += last - end;
    if (last < start + n) kept.push_back(last % n);
    anchor = last;
    end = last + 1;
  }
  if (dropped == 0) return 0;
  // In the profile's order from its first kept vertex (the section's arc
  // length, and the bolt pattern laid out along it, start there).
  std::rotate(kept.begin(), std::min_element(kept.begin(), kept.end()), kept.end());
  std::vector<SectionVertex> out;
  for (std::size_t i : kept) {
    out.push_back(pts[i]);
    out.back().joins = std::move(joins[i]);
  }
  pts = std::move(out);
  return dropped;
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

std::vector<std::size_t> SectionPolygon::segments_under(std::size_t i, const Eigen::Vector2d& a,
                                                        const Eigen::Vector2d& b) const {
  const SectionVertex& v = vertices[i % size()];
  const Eigen::Vector2d o = v.p, d = at(i + 1) - o;
  const double ta = (a - o).dot(d) / d.squaredNorm(), tb = (b - o).dot(d) / d.squaredNorm();
  const double lo = std::min(ta, tb), hi = std::max(ta, tb);
  // Segment k runs from its join to the next one (the first from 0, the
  // last to 1); it is under the part when the two overlap.
  std::vector<std::size_t> out;
  double from = 0;
  std::size_t segment = v.segment;
  for (std::size_t k = 0; k <= v.joins.size(); ++k) {
    const double to = k < v.joins.size() ? v.joins[k].first : 1;
    if (to > lo && from < hi) out.push_back(segment);
    if (k < v.joins.size()) std::tie(from, segment) = v.joins[k];
  }
  if (out.empty()) out.push_back(v.segment);  // a part of no length
  return out;
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
  const std::size_t drawn = kept.size();
  const std::size_t merged = merge_line_chords(kept, out.segment_kinds, sagitta_m);
  if (merged > 0) {
    std::ostringstream note;
    note << "the profile's lines between its corners are drawn as " << drawn << " chords; "
         << merged << " of their joints, within " << sagitta_m * 1000
         << " mm of a straight line, are merged: the section has " << kept.size()
         << " edges (the chords' sagitta, as for an arc)";
    out.notes.push_back(note.str());
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
