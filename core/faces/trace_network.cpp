#include "core/faces/trace_network.h"

#include "core/faces/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/faces/tolerances.h"

namespace rockface::faces {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Counter-clockwise angle from a to b in [0, 2 pi).
double ccw_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  double t = std::atan2(cross2(a, b), a.dot(b));
  if (t < 0) t += kTwoPi;
  if (t >= kTwoPi) t = 0;
  return t;
}

std::string where_trace(const std::vector<TraceInput>& traces, int i) {
  return "traces[" + std::to_string(i) + "] (" + traces[i].id + ")";
}

std::string fmt(double v, int precision = 3) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

// A trace's straight stretch on one patch: p + t u, t in [t0, t1] (2D, patch frame).
struct Segment {
  int patch = -1;
  int group = -1;
  Eigen::Vector2d p = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::UnitX();
  double t0 = 0, t1 = 0;
  bool free0 = false, free1 = false;  // a marked end (may be extended), not a patch edge
  int on_edge = -1;                   // patch edge it was laid onto
  bool alive = true;
  std::vector<std::pair<double, int>> points;  // (parameter, point) on it
  double length() const { return t1 - t0; }
  Eigen::Vector2d at(double t) const { return p + t * u; }
};

struct Hit {
  int patch = -1;
  int a = -1;
  double s = 0;
  int b = -1;         // segment index, or -1 when the other is a patch edge
  int edge = -1;      // patch edge index when b == -1
  double t = 0;       // parameter on b (or on the patch edge)
  Eigen::Vector2d x;  // 2D point
  bool kept = true;
};

// Points to be clustered into vertices; higher rank wins the position.
struct Candidate {
  Eigen::Vector3d x;
  int rank = 0;  // 3 patch corner, 2 on a patch edge, 1 crossing, 0 marked end
};

// Parameter interval of the line p + t u inside a convex counter-clockwise polygon.
bool clip_line(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p,
               const Eigen::Vector2d& u, double& lo, double& hi) {
  lo = -kInf;
  hi = kInf;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = poly[i], e = poly[(i + 1) % n] - a;
    if (e.norm() == 0) continue;
    // Inside: cross(e, x - a) >= 0 with x = p + t u.
    const double c0 = cross2(e, p - a), c1 = cross2(e, u);
    if (std::abs(c1) < kParallelSine * e.norm()) {
      if (c0 < 0) return false;
      continue;
    }
    const double t = -c0 / c1;
    if (c1 > 0)
      lo = std::max(lo, t);
    else
      hi = std::min(hi, t);
  }
  return lo < hi;
}

// Distance from x to the segment ab and the parameter (0..|ab|) of its foot.
double distance_to_segment(const Eigen::Vector3d& x, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b, double& param) {
  const Eigen::Vector3d d = b - a;
  const double len = d.norm();
  param = std::clamp((x - a).dot(d) / (len * len), 0.0, 1.0) * len;
  return (a + d * (param / len) - x).norm();
}

}  // namespace

bool NetworkEdge::outline() const {
  int boundaries = 0;
  for (const auto& p : patches) boundaries += p.boundary ? 1 : 0;
  return boundaries == 1;
}

int TraceNetwork::next(int h) const {
  const int v = target(h);
  const int back = h ^ 1;
  const auto& around = around_[v].half_edges;
  const int deg = static_cast<int>(around.size());
  return around[(slot_[back] - 1 + deg) % deg];
}

TraceNetwork TraceNetwork::build(const FreeSurface& surface, const std::vector<TraceInput>& traces,
                                 const NetworkOptions& options) {
  TraceNetwork net;
  const double tol = options.snap_tolerance;
  const auto& patches = surface.patches();
  net.mapped_.assign(traces.size(), false);
  for (const TraceInput& t : traces) net.trace_points_.push_back(t.points);
  net.snap_tolerance_ = options.snap_tolerance;

  double scale = 0;
  for (const auto& p : patches)
    for (const auto& q : p.polygon) scale = std::max(scale, (q - patches[0].polygon[0]).norm());
  const double slack = kParamSlackRel * std::max(scale, 1.0);

  // --- Planes and straight stretches per patch -------------------------------
  std::vector<Segment> segs;
  std::vector<PlaneGroup> groups;
  for (size_t i = 0; i < traces.size(); ++i) {
    const TraceInput& tr = traces[i];
    const std::string where = where_trace(traces, static_cast<int>(i));
    if (tr.points.size() < 2) {
      net.notes_.push_back(where + ": has " + std::to_string(tr.points.size()) +
                           " point(s); a trace needs at least two - left out of the map");
      continue;
    }
    const auto on = points_on_patches(tr.points, surface, tol);
    std::vector<int> touched;
    int off = 0;
    for (const auto& o : on) {
      off += o.empty() ? 1 : 0;
      touched.insert(touched.end(), o.begin(), o.end());
    }
    // A patch the marking crosses between two of its points (a narrow piece
    // of a patch split into convex ones) is touched too: the part of each
    // marked segment lying in the patch's plane and polygon.
    auto crossing = [&](size_t k, size_t j, double& lo, double& hi) {
      const SurfacePatch& P = patches[k];
      const Eigen::Vector3d& a = tr.points[j];
      const Eigen::Vector3d& b = tr.points[j + 1];
      if (std::abs(P.height(a)) > tol || std::abs(P.height(b)) > tol) return false;
      const Eigen::Vector2d a2 = P.to2d(a), d2 = P.to2d(b) - a2;
      if (d2.norm() <= tol) return false;
      if (!clip_line(P.polygon2d, a2, d2, lo, hi)) return false;
      lo = std::max(lo, 0.0);
      hi = std::min(hi, 1.0);
      return lo < hi;
    };
    for (size_t k = 0; k < patches.size(); ++k)
      for (size_t j = 0; j + 1 < tr.points.size(); ++j) {
        double lo = 0, hi = 0;
        if (crossing(k, j, lo, hi)) touched.push_back(static_cast<int>(k));
      }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    if (off > 0 && !touched.empty())
      net.notes_.push_back(where + ": " + std::to_string(off) + " of its points lie more than " +
                           fmt(tol) + " m off the surface and are ignored");
    if (touched.empty()) {
      net.notes_.push_back(where + ": lies off the surface (no point within " + fmt(tol) +
                           " m of a patch) - left out of the map");
      continue;
    }
    const TracePlaneResult rp = resolve_trace_plane(tr, surface, touched, tol);
    if (!rp.plane) {
      net.notes_.push_back(where + ": " + rp.problem + " - left out of blocks");
      continue;
    }
    if (!rp.problem.empty()) net.notes_.push_back(where + ": " + rp.problem);
    const geometry::Plane& jp = rp.plane->plane;
    const int g = static_cast<int>(groups.size());
    bool made = false;
    for (int k : touched) {
      const SurfacePatch& P = patches[k];
      const Eigen::Vector3d u3 = jp.normal.cross(P.outward);
      if (u3.norm() < kTraceOnPatchSine) {
        net.notes_.push_back(where + ": its plane is the plane of " + surface.where(k) +
                             "; it has no trace line there");
        continue;
      }
      const Eigen::Vector2d u = P.dir2d(u3).normalized();
      const Eigen::Vector2d gn(jp.normal.dot(P.e1), jp.normal.dot(P.e2));
      const Eigen::Vector2d p0 = gn * (jp.offset - jp.normal.dot(P.origin)) / gn.squaredNorm();
      double tmin = kInf, tmax = -kInf;
      bool to_lo = false, to_hi = false;
      auto on_k = [&](size_t j) { return std::find(on[j].begin(), on[j].end(), k) != on[j].end(); };
      for (size_t j = 0; j < tr.points.size(); ++j)
        if (on_k(j)) {
          const double t = u.dot(P.to2d(tr.points[j]) - p0);
          tmin = std::min(tmin, t);
          tmax = std::max(tmax, t);
        }
      for (size_t j = 0; j + 1 < tr.points.size(); ++j) {
        double lo = 0, hi = 0;
        if (!crossing(k, j, lo, hi)) continue;
        const Eigen::Vector2d a2 = P.to2d(tr.points[j]), d2 = P.to2d(tr.points[j + 1]) - a2;
        for (double f : {lo, hi}) {
          const double t = u.dot(a2 + f * d2 - p0);
          tmin = std::min(tmin, t);
          tmax = std::max(tmax, t);
        }
      }
      // Where the marking goes on to another patch, the stretch reaches the patch edge.
      for (size_t j = 0; j + 1 < tr.points.size(); ++j) {
        const bool a = on_k(j), b = on_k(j + 1);
        if (a == b || on[a ? j + 1 : j].empty()) continue;
        const Eigen::Vector3d dir =
            a ? tr.points[j + 1] - tr.points[j] : tr.points[j] - tr.points[j + 1];
        (u.dot(P.dir2d(dir)) > 0 ? to_hi : to_lo) = true;
      }
      double a = 0, b = 0;
      if (!clip_line(P.polygon2d, p0, u, a, b)) continue;
      Segment s;
      s.patch = k;
      s.group = g;
      s.p = p0;
      s.u = u;
      s.t0 = to_lo ? a : std::max(tmin, a);
      s.t1 = to_hi ? b : std::min(tmax, b);
      if (s.length() <= tol) continue;
      s.free0 = s.t0 > a + slack;
      s.free1 = s.t1 < b - slack;
      segs.push_back(s);
      made = true;
    }
    if (!made) {
      net.notes_.push_back(where + ": no stretch of it longer than the snap tolerance (" +
                           fmt(tol) + " m) lies on the surface - left out of the map");
      continue;
    }
    PlaneGroup pg;
    pg.name = tr.id;
    pg.traces = {static_cast<int>(i)};
    pg.plane = *rp.plane;
    pg.joint = tr.joint;
    groups.push_back(pg);
    net.mapped_[i] = true;
  }

  // --- Stretches along a patch edge are laid onto it --------------------------
  for (auto& s : segs) {
    const SurfacePatch& P = patches[s.patch];
    const size_t n = P.polygon2d.size();
    for (size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d A = P.polygon2d[k], B = P.polygon2d[(k + 1) % n];
      const double len = (B - A).norm();
      const Eigen::Vector2d e = (B - A) / len;
      const Eigen::Vector2d q0 = s.at(s.t0), q1 = s.at(s.t1);
      if (std::abs(cross2(e, q0 - A)) > tol || std::abs(cross2(e, q1 - A)) > tol) continue;
      double r0 = e.dot(q0 - A), r1 = e.dot(q1 - A);
      bool f0 = s.free0, f1 = s.free1;
      if (r0 > r1) {
        std::swap(r0, r1);
        std::swap(f0, f1);
      }
      s.p = A;
      s.u = e;
      s.t0 = std::max(r0, 0.0);
      s.t1 = std::min(r1, len);
      s.free0 = f0 && s.t0 > slack;
      s.free1 = f1 && s.t1 < len - slack;
      s.on_edge = static_cast<int>(k);
      break;
    }
  }

  // --- Stretches that run together are one (a trace marked in pieces) ---------
  UnionFind group_uf(groups.size());
  // Traces of one scene joint that meet (a point of one within the snap
  // tolerance of the other) and whose planes coincide (located within the
  // tolerance) are one discontinuity: typically the pieces of a joint's
  // trace marked patch by patch. Kept apart they would bound a block twice
  // by one plane. Parallel traces of the set that do not meet stay apart,
  // however close their planes: they are other joints of the set.
  auto meet = [&](const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q) {
    double param = 0;
    for (const auto& x : p)
      for (size_t j = 0; j + 1 < q.size(); ++j)
        if (distance_to_segment(x, q[j], q[j + 1], param) <= tol) return true;
    return false;
  };
  for (size_t a = 0; a < groups.size(); ++a)
    for (size_t b = a + 1; b < groups.size(); ++b) {
      const PlaneGroup& ga = groups[a];
      const PlaneGroup& gb = groups[b];
      if (!ga.joint || !gb.joint || ga.joint->index != gb.joint->index ||
          ga.plane.source != TracePlaneSource::Joint || gb.plane.source != TracePlaneSource::Joint)
        continue;
      if (std::abs(ga.plane.plane.offset - gb.plane.plane.offset) > tol) continue;
      const auto& pa = traces[ga.traces.front()].points;
      const auto& pb = traces[gb.traces.front()].points;
      if (meet(pa, pb) || meet(pb, pa)) group_uf.unite(static_cast<int>(a), static_cast<int>(b));
    }
  std::vector<std::vector<int>> by_patch(patches.size());
  for (size_t i = 0; i < segs.size(); ++i) by_patch[segs[i].patch].push_back(static_cast<int>(i));
  for (auto& list : by_patch) {
    bool changed = true;
    while (changed) {
      changed = false;
      for (size_t x = 0; x < list.size() && !changed; ++x)
        for (size_t y = x + 1; y < list.size() && !changed; ++y) {
          Segment& a = segs[list[x]];
          Segment& b = segs[list[y]];
          if (!a.alive || !b.alive) continue;
          const double longest = std::max(a.length(), b.length());
          if (std::abs(cross2(a.u, b.u)) * longest > tol) continue;
          const Eigen::Vector2d b0 = b.at(b.t0), b1 = b.at(b.t1), a0 = a.at(a.t0), a1 = a.at(a.t1);
          if (std::abs(cross2(a.u, b0 - a.p)) > tol || std::abs(cross2(a.u, b1 - a.p)) > tol ||
              std::abs(cross2(b.u, a0 - b.p)) > tol || std::abs(cross2(b.u, a1 - b.p)) > tol)
            continue;
          double r0 = a.u.dot(b0 - a.p), r1 = a.u.dot(b1 - a.p);
          bool f0 = b.free0, f1 = b.free1;
          if (r0 > r1) {
            std::swap(r0, r1);
            std::swap(f0, f1);
          }
          if (std::max(a.t0, r0) > std::min(a.t1, r1) + tol) continue;
          // The survivor keeps the line of a stretch laid on a patch edge, else
          // of the longer one (the better-determined line).
          Segment* keep = &a;
          Segment* drop = &b;
          if ((b.on_edge >= 0 && a.on_edge < 0) ||
              (b.on_edge == a.on_edge && b.length() > a.length())) {
            keep = &b;
            drop = &a;
          }
          double d0 = keep->u.dot(drop->at(drop->t0) - keep->p),
                 d1 = keep->u.dot(drop->at(drop->t1) - keep->p);
          bool g0 = drop->free0, g1 = drop->free1;
          if (d0 > d1) {
            std::swap(d0, d1);
            std::swap(g0, g1);
          }
          if (d0 < keep->t0) {
            keep->t0 = d0;
            keep->free0 = g0;
          }
          if (d1 > keep->t1) {
            keep->t1 = d1;
            keep->free1 = g1;
          }
          const PlaneGroup& ga = groups[group_uf.find(keep->group)];
          const PlaneGroup& gb = groups[group_uf.find(drop->group)];
          const double angle =
              std::acos(std::min(1.0, std::abs(ga.plane.plane.normal.dot(gb.plane.plane.normal))));
          if (group_uf.find(keep->group) != group_uf.find(drop->group) &&
              angle > std::max(options.orientation_uncertainty, deg_to_rad(1.0)))
            net.notes_.push_back(
                "traces " + ga.name + " and " + gb.name + " run together on " +
                surface.where(keep->patch) + " but their planes differ by " +
                fmt(rad_to_deg(angle), 2) +
                " degrees; they are taken as one "
                "discontinuity with the plane of " +
                groups[std::min(group_uf.find(keep->group), group_uf.find(drop->group))].name);
          group_uf.unite(keep->group, drop->group);
          drop->alive = false;
          changed = true;
        }
    }
  }
  // Groups: the one of the earliest trace represents the merged discontinuity.
  std::vector<int> group_index(groups.size(), -1);
  for (size_t g = 0; g < groups.size(); ++g) {
    const int r = group_uf.find(static_cast<int>(g));
    if (group_index[r] < 0) {
      group_index[r] = static_cast<int>(net.groups_.size());
      net.groups_.push_back(groups[r]);
    } else if (r != static_cast<int>(g)) {
      auto& t = net.groups_[group_index[r]].traces;
      t.insert(t.end(), groups[g].traces.begin(), groups[g].traces.end());
    }
  }
  for (size_t g = 0; g < groups.size(); ++g) group_index[g] = group_index[group_uf.find(g)];
  for (auto& pg : net.groups_) std::sort(pg.traces.begin(), pg.traces.end());
  for (auto& s : segs) s.group = group_index[s.group];

  // --- Crossings and extensions ---------------------------------------------
  std::vector<Hit> hits;
  for (size_t k = 0; k < patches.size(); ++k) {
    const SurfacePatch& P = patches[k];
    const size_t n = P.polygon2d.size();
    std::vector<int> list;
    for (int i : by_patch[k])
      if (segs[i].alive) list.push_back(i);
    auto reach = [&](const Segment& s, double& lo, double& hi) {
      lo = s.t0 - (s.free0 ? tol : slack);
      hi = s.t1 + (s.free1 ? tol : slack);
    };
    for (size_t x = 0; x < list.size(); ++x) {
      const Segment& a = segs[list[x]];
      double alo, ahi;
      reach(a, alo, ahi);
      for (size_t y = x + 1; y < list.size(); ++y) {
        const Segment& b = segs[list[y]];
        const double den = cross2(a.u, b.u);
        if (std::abs(den) < kParallelSine) continue;
        const Eigen::Vector2d d = b.p - a.p;
        const double s = cross2(d, b.u) / den, t = cross2(d, a.u) / den;
        double blo, bhi;
        reach(b, blo, bhi);
        if (s < alo || s > ahi || t < blo || t > bhi) continue;
        hits.push_back({static_cast<int>(k), list[x], s, list[y], -1, t, a.at(s)});
      }
      for (size_t e = 0; e < n; ++e) {
        if (static_cast<int>(e) == a.on_edge) continue;
        const Eigen::Vector2d A = P.polygon2d[e], B = P.polygon2d[(e + 1) % n];
        const double len = (B - A).norm();
        const Eigen::Vector2d ue = (B - A) / len;
        const double den = cross2(a.u, ue);
        if (std::abs(den) < kParallelSine) continue;
        const Eigen::Vector2d d = A - a.p;
        const double s = cross2(d, ue) / den, t = cross2(d, a.u) / den;
        if (s < alo || s > ahi || t < -tol || t > len + tol) continue;
        hits.push_back({static_cast<int>(k), list[x], s, -1, static_cast<int>(e), t, a.at(s)});
      }
    }
  }
  // A marked end reaches only the nearest trace or edge ahead of it.
  {
    std::vector<int> best_lo(segs.size(), -1), best_hi(segs.size(), -1);
    auto consider = [&](int seg, double param, int h) {
      const Segment& s = segs[seg];
      if (param < s.t0 - slack) {
        if (best_lo[seg] < 0 ||
            param > (hits[best_lo[seg]].a == seg ? hits[best_lo[seg]].s : hits[best_lo[seg]].t))
          best_lo[seg] = h;
      } else if (param > s.t1 + slack) {
        if (best_hi[seg] < 0 ||
            param < (hits[best_hi[seg]].a == seg ? hits[best_hi[seg]].s : hits[best_hi[seg]].t))
          best_hi[seg] = h;
      }
    };
    for (size_t h = 0; h < hits.size(); ++h) {
      consider(hits[h].a, hits[h].s, static_cast<int>(h));
      if (hits[h].b >= 0) consider(hits[h].b, hits[h].t, static_cast<int>(h));
    }
    auto ok = [&](int seg, double param, int h) {
      const Segment& s = segs[seg];
      if (param < s.t0 - slack) return best_lo[seg] == h;
      if (param > s.t1 + slack) return best_hi[seg] == h;
      return true;
    };
    for (size_t h = 0; h < hits.size(); ++h) {
      Hit& hit = hits[h];
      hit.kept = ok(hit.a, hit.s, static_cast<int>(h)) &&
                 (hit.b < 0 || ok(hit.b, hit.t, static_cast<int>(h)));
    }
    for (size_t h = 0; h < hits.size(); ++h) {
      const Hit& hit = hits[h];
      if (!hit.kept) continue;
      for (auto [seg, param] : {std::pair{hit.a, hit.s}, std::pair{hit.b, hit.t}}) {
        if (seg < 0) continue;
        Segment& s = segs[seg];
        if (param < s.t0) s.t0 = param, s.free0 = false;
        if (param > s.t1) s.t1 = param, s.free1 = false;
      }
    }
  }

  // --- Vertices: crossings, corners and ends within the tolerance are one -----
  std::vector<Candidate> cands;
  std::vector<std::vector<int>> corner_cand(patches.size());
  for (size_t k = 0; k < patches.size(); ++k)
    for (const auto& c : patches[k].polygon) {
      corner_cand[k].push_back(static_cast<int>(cands.size()));
      cands.push_back({c, 3});
    }
  for (const Hit& hit : hits) {
    if (!hit.kept) continue;
    const int c = static_cast<int>(cands.size());
    cands.push_back({patches[hit.patch].to3d(hit.x), hit.b < 0 ? 2 : 1});
    segs[hit.a].points.push_back({hit.s, c});
    if (hit.b >= 0) segs[hit.b].points.push_back({hit.t, c});
  }
  for (auto& s : segs) {
    if (!s.alive) continue;
    for (double t : {s.t0, s.t1}) {
      bool have = false;
      for (const auto& [param, c] : s.points) have = have || std::abs(param - t) <= slack;
      if (have) continue;
      const bool on_edge = (t == s.t0 ? !s.free0 : !s.free1) || s.on_edge >= 0;
      const int c = static_cast<int>(cands.size());
      cands.push_back({patches[s.patch].to3d(s.at(t)), on_edge ? 2 : 0});
      s.points.push_back({t, c});
    }
  }
  UnionFind cuf(cands.size());
  {
    struct KeyHash {
      size_t operator()(const std::array<long long, 3>& k) const {
        return static_cast<size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
      }
    };
    std::unordered_map<std::array<long long, 3>, std::vector<int>, KeyHash> grid;
    auto key = [&](const Eigen::Vector3d& x) {
      return std::array<long long, 3>{static_cast<long long>(std::floor(x.x() / tol)),
                                      static_cast<long long>(std::floor(x.y() / tol)),
                                      static_cast<long long>(std::floor(x.z() / tol))};
    };
    for (size_t i = 0; i < cands.size(); ++i) grid[key(cands[i].x)].push_back(static_cast<int>(i));
    for (size_t i = 0; i < cands.size(); ++i) {
      const auto k0 = key(cands[i].x);
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz) {
            auto it = grid.find({k0[0] + dx, k0[1] + dy, k0[2] + dz});
            if (it == grid.end()) continue;
            for (int j : it->second)
              if (j > static_cast<int>(i) && (cands[j].x - cands[i].x).norm() <= tol)
                cuf.unite(static_cast<int>(i), j);
          }
    }
  }
  std::vector<int> vertex_of(cands.size(), -1);
  {
    std::vector<int> best_rank(cands.size(), -1);
    for (size_t i = 0; i < cands.size(); ++i) {
      const int r = cuf.find(static_cast<int>(i));
      best_rank[r] = std::max(best_rank[r], cands[i].rank);
    }
    std::vector<Eigen::Vector3d> sum(cands.size(), Eigen::Vector3d::Zero());
    std::vector<int> count(cands.size(), 0);
    for (size_t i = 0; i < cands.size(); ++i) {
      const int r = cuf.find(static_cast<int>(i));
      if (cands[i].rank != best_rank[r]) continue;
      sum[r] += cands[i].x;
      ++count[r];
    }
    for (size_t i = 0; i < cands.size(); ++i) {
      const int r = cuf.find(static_cast<int>(i));
      if (vertex_of[r] < 0) {
        vertex_of[r] = static_cast<int>(net.vertices_.size());
        net.vertices_.push_back(sum[r] / count[r]);
      }
      vertex_of[i] = vertex_of[r];
    }
  }

  // --- Edges ------------------------------------------------------------------
  std::map<std::pair<int, int>, int> edge_of;
  auto add_edge = [&](int a, int b, int patch, bool boundary, int group) {
    if (a == b) return;
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    auto it = edge_of.find(key);
    int e;
    if (it == edge_of.end()) {
      e = static_cast<int>(net.edges_.size());
      edge_of[key] = e;
      NetworkEdge ne;
      ne.v0 = key.first;
      ne.v1 = key.second;
      net.edges_.push_back(ne);
    } else {
      e = it->second;
    }
    NetworkEdge& ne = net.edges_[e];
    const bool forward = a == ne.v0;
    bool found = false;
    for (auto& op : ne.patches)
      if (op.patch == patch) {
        found = true;
        if (boundary && !op.boundary) {
          op.boundary = true;
          op.forward = forward;
        }
      }
    if (!found) {
      for (const auto& op : ne.patches)
        if (boundary && op.boundary && op.forward == forward)
          throw InputError(surface.where(patch),
                           "runs along its edge shared with " + surface.where(op.patch) +
                               " in the same direction: list every patch counter-clockwise "
                               "seen from the open side");
      ne.patches.push_back({patch, boundary, forward});
    }
    if (group >= 0) {
      if (ne.group >= 0 && ne.group != group)
        net.notes_.push_back(
            "traces " + net.groups_[ne.group].name + " and " + net.groups_[group].name +
            " run along the same stretch; it keeps the plane of " + net.groups_[ne.group].name);
      else
        ne.group = group;
    }
  };
  for (auto& s : segs) {
    if (!s.alive) continue;
    std::sort(s.points.begin(), s.points.end());
    for (size_t i = 0; i + 1 < s.points.size(); ++i)
      add_edge(vertex_of[s.points[i].second], vertex_of[s.points[i + 1].second], s.patch,
               s.on_edge >= 0, s.group);
  }
  for (size_t k = 0; k < patches.size(); ++k) {
    const SurfacePatch& P = patches[k];
    const size_t n = P.polygon.size();
    for (size_t e = 0; e < n; ++e) {
      const Eigen::Vector3d A = P.polygon[e], B = P.polygon[(e + 1) % n];
      std::vector<std::pair<double, int>> on;
      for (size_t v = 0; v < net.vertices_.size(); ++v) {
        double param = 0;
        if (distance_to_segment(net.vertices_[v], A, B, param) <= tol)
          on.push_back({param, static_cast<int>(v)});
      }
      std::sort(on.begin(), on.end());
      for (size_t i = 0; i + 1 < on.size(); ++i)
        add_edge(on[i].second, on[i + 1].second, static_cast<int>(k), true, -1);
    }
  }

  // --- Order around each vertex, unfolding the patches that meet there -------
  const size_t nv = net.vertices_.size();
  std::vector<std::vector<int>> incident(nv);
  for (size_t e = 0; e < net.edges_.size(); ++e) {
    incident[net.edges_[e].v0].push_back(static_cast<int>(2 * e));
    incident[net.edges_[e].v1].push_back(static_cast<int>(2 * e + 1));
  }
  net.around_.resize(nv);
  net.slot_.assign(2 * net.edges_.size(), -1);
  for (size_t v = 0; v < nv; ++v) {
    struct PatchAt {
      int patch = -1;
      int start = -1, end = -1;  // outgoing half-edges along the patch boundary
      Eigen::Vector2d start_dir = Eigen::Vector2d::UnitX();
      double sector = kTwoPi, offset = 0;
      int next = -1;
      bool has_prev = false;
    };
    std::vector<PatchAt> at;
    auto find_at = [&](int patch) -> PatchAt& {
      for (auto& a : at)
        if (a.patch == patch) return a;
      at.push_back({});
      at.back().patch = patch;
      return at.back();
    };
    auto dir2 = [&](int h, int patch) {
      const SurfacePatch& P = patches[patch];
      return P.dir2d(net.vertices_[net.target(h)] - net.vertices_[v]).normalized().eval();
    };
    for (int h : incident[v]) {
      const NetworkEdge& e = net.edges_[h / 2];
      const bool out_forward = (h % 2 == 0);  // h runs v0 -> v1
      for (const auto& op : e.patches) {
        PatchAt& a = find_at(op.patch);
        if (!op.boundary) continue;
        // The patch's counter-clockwise boundary leaves v along h when they agree.
        if (op.forward == out_forward)
          a.start = h;
        else
          a.end = h;
      }
    }
    for (auto& a : at) {
      if (a.start >= 0 && a.end >= 0) {
        a.start_dir = dir2(a.start, a.patch);
        a.sector = ccw_angle(a.start_dir, dir2(a.end, a.patch));
        if (a.sector <= 0) a.sector = kTwoPi;
      } else {
        a.start = a.end = -1;
        for (int h : incident[v]) {
          bool on = false;
          for (const auto& op : net.edges_[h / 2].patches) on = on || op.patch == a.patch;
          if (on) {
            a.start_dir = dir2(h, a.patch);
            break;
          }
        }
      }
    }
    for (size_t i = 0; i < at.size(); ++i)
      for (size_t j = 0; j < at.size(); ++j)
        if (i != j && at[i].end >= 0 && at[i].end == at[j].start) {
          at[i].next = static_cast<int>(j);
          at[j].has_prev = true;
        }
    double sum = 0;
    int open = 0;
    for (const auto& a : at) {
      sum += a.sector;
      // A patch around an inner vertex covers the full turn: nothing is open there.
      open += (a.has_prev || a.start < 0) ? 0 : 1;
    }
    const double gap = open > 0 ? std::max((kTwoPi - sum) / open, std::numbers::pi / 4) : 0;
    AroundVertex& av = net.around_[v];
    std::vector<bool> placed(at.size(), false);
    double cursor = 0;
    auto run_chain = [&](int first) {
      for (int i = first; i >= 0 && !placed[i]; i = at[i].next) {
        placed[i] = true;
        at[i].offset = cursor;
        av.sectors.push_back({at[i].patch, cursor, cursor + at[i].sector});
        cursor += at[i].sector;
      }
    };
    for (size_t i = 0; i < at.size(); ++i)
      if (!at[i].has_prev && at[i].start >= 0) {
        run_chain(static_cast<int>(i));
        cursor += gap;
      }
    for (size_t i = 0; i < at.size(); ++i)
      if (!placed[i]) run_chain(static_cast<int>(i));
    av.total = cursor;
    std::vector<std::pair<double, int>> order;
    for (int h : incident[v]) {
      double pos = -1;
      for (const auto& op : net.edges_[h / 2].patches) {
        const PatchAt& a = find_at(op.patch);
        if (h == a.start)
          pos = a.offset;
        else if (h == a.end)
          pos = a.offset + a.sector;
        else
          pos = a.offset + std::min(ccw_angle(a.start_dir, dir2(h, op.patch)), a.sector);
        if (op.boundary) break;  // a boundary position is exact; prefer it
      }
      order.push_back({pos, h});
    }
    std::sort(order.begin(), order.end());
    for (size_t i = 0; i < order.size(); ++i) {
      av.half_edges.push_back(order[i].second);
      av.angle.push_back(order[i].first);
      net.slot_[order[i].second] = static_cast<int>(i);
    }
  }
  return net;
}

}  // namespace rockface::faces
