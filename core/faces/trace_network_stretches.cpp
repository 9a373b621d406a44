// Phases 1 to 3 of TraceNetwork::build: from the marked traces to the
// straight stretches on the patches, laid onto patch edges and merged where
// they run together.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/faces/tolerances.h"
#include "core/faces/trace_network_phases.h"
#include "core/faces/union_find.h"

namespace rockface::faces::network_phases {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string where_trace(const std::vector<TraceInput>& traces, int i) {
  return "traces[" + std::to_string(i) + "] (" + traces[i].id + ")";
}

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

}  // namespace

Stretches trace_stretches(const FreeSurface& surface, const std::vector<TraceInput>& traces,
                          double tolerance, double slack, std::vector<bool>& mapped,
                          std::vector<std::string>& notes) {
  const auto& patches = surface.patches();
  std::vector<Segment> segments;
  std::vector<PlaneGroup> groups;
  for (size_t i = 0; i < traces.size(); ++i) {
    const TraceInput& tr = traces[i];
    const std::string where = where_trace(traces, static_cast<int>(i));
    if (tr.points.size() < 2) {
      notes.push_back(where + ": has " + std::to_string(tr.points.size()) +
                      " point(s); a trace needs at least two - left out of the map");
      continue;
    }
    const auto on = points_on_patches(tr.points, surface, tolerance);
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
      if (std::abs(P.height(a)) > tolerance || std::abs(P.height(b)) > tolerance) return false;
      const Eigen::Vector2d a2 = P.to2d(a), d2 = P.to2d(b) - a2;
      if (d2.norm() <= tolerance) return false;
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
      notes.push_back(where + ": " + std::to_string(off) + " of its points lie more than " +
                      format_significant(tolerance, 3) + " m off the surface and are ignored");
    if (touched.empty()) {
      notes.push_back(where + ": lies off the surface (no point within " +
                      format_significant(tolerance, 3) + " m of a patch) - left out of the map");
      continue;
    }
    const TracePlaneResult rp = resolve_trace_plane(tr, surface, touched, tolerance);
    if (!rp.plane) {
      notes.push_back(where + ": " + rp.problem + " - left out of blocks");
      continue;
    }
    if (!rp.problem.empty()) notes.push_back(where + ": " + rp.problem);
    const geometry::Plane& jp = rp.plane->plane;
    const int g = static_cast<int>(groups.size());
    bool made = false;
    for (int k : touched) {
      const SurfacePatch& P = patches[k];
      const Eigen::Vector3d u3 = jp.normal.cross(P.outward);
      if (u3.norm() < kTraceOnPatchSine) {
        notes.push_back(where + ": its plane is the plane of " + surface.where(k) +
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
      if (s.length() <= tolerance) continue;
      s.free0 = s.t0 > a + slack;
      s.free1 = s.t1 < b - slack;
      segments.push_back(s);
      made = true;
    }
    if (!made) {
      notes.push_back(where + ": no stretch of it longer than the snap tolerance (" +
                      format_significant(tolerance, 3) +
                      " m) lies on the surface - left out of the map");
      continue;
    }
    PlaneGroup pg;
    pg.name = tr.id;
    pg.traces = {static_cast<int>(i)};
    pg.plane = *rp.plane;
    pg.joint = tr.joint;
    groups.push_back(pg);
    mapped[i] = true;
  }
  return {std::move(segments), std::move(groups)};
}

void lay_onto_patch_edges(std::vector<Segment>& segments, const FreeSurface& surface,
                          double tolerance, double slack) {
  const auto& patches = surface.patches();
  for (auto& s : segments) {
    const SurfacePatch& P = patches[s.patch];
    const size_t n = P.polygon2d.size();
    for (size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d A = P.polygon2d[k], B = P.polygon2d[(k + 1) % n];
      const double len = (B - A).norm();
      const Eigen::Vector2d e = (B - A) / len;
      const Eigen::Vector2d q0 = s.at(s.t0), q1 = s.at(s.t1);
      if (std::abs(cross2(e, q0 - A)) > tolerance || std::abs(cross2(e, q1 - A)) > tolerance)
        continue;
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
}

std::vector<PlaneGroup> merge_stretches(std::vector<Segment>& segments,
                                        const std::vector<PlaneGroup>& groups,
                                        const std::vector<std::vector<int>>& by_patch,
                                        const std::vector<TraceInput>& traces,
                                        const FreeSurface& surface, const NetworkOptions& options,
                                        std::vector<std::string>& notes) {
  const double tolerance = options.snap_tolerance;
  std::vector<PlaneGroup> merged;
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
        if (distance_to_segment(x, q[j], q[j + 1], param) <= tolerance) return true;
    return false;
  };
  for (size_t a = 0; a < groups.size(); ++a)
    for (size_t b = a + 1; b < groups.size(); ++b) {
      const PlaneGroup& ga = groups[a];
      const PlaneGroup& gb = groups[b];
      if (!ga.joint || !gb.joint || ga.joint->index != gb.joint->index ||
          ga.plane.source != TracePlaneSource::Joint || gb.plane.source != TracePlaneSource::Joint)
        continue;
      if (std::abs(ga.plane.plane.offset - gb.plane.plane.offset) > tolerance) continue;
      const auto& pa = traces[ga.traces.front()].points;
      const auto& pb = traces[gb.traces.front()].points;
      if (meet(pa, pb) || meet(pb, pa)) group_uf.unite(static_cast<int>(a), static_cast<int>(b));
    }
  for (auto& list : by_patch) {
    bool changed = true;
    while (changed) {
      changed = false;
      for (size_t x = 0; x < list.size() && !changed; ++x)
        for (size_t y = x + 1; y < list.size() && !changed; ++y) {
          Segment& a = segments[list[x]];
          Segment& b = segments[list[y]];
          if (!a.alive || !b.alive) continue;
          const double longest = std::max(a.length(), b.length());
          if (std::abs(cross2(a.u, b.u)) * longest > tolerance) continue;
          const Eigen::Vector2d b0 = b.at(b.t0), b1 = b.at(b.t1), a0 = a.at(a.t0), a1 = a.at(a.t1);
          if (std::abs(cross2(a.u, b0 - a.p)) > tolerance ||
              std::abs(cross2(a.u, b1 - a.p)) > tolerance ||
              std::abs(cross2(b.u, a0 - b.p)) > tolerance ||
              std::abs(cross2(b.u, a1 - b.p)) > tolerance)
            continue;
          double r0 = a.u.dot(b0 - a.p), r1 = a.u.dot(b1 - a.p);
          bool f0 = b.free0, f1 = b.free1;
          if (r0 > r1) {
            std::swap(r0, r1);
            std::swap(f0, f1);
          }
          if (std::max(a.t0, r0) > std::min(a.t1, r1) + tolerance) continue;
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
            notes.push_back(
                "traces " + ga.name + " and " + gb.name + " run together on " +
                surface.where(keep->patch) + " but their planes differ by " +
                format_significant(rad_to_deg(angle), 2) +
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
      group_index[r] = static_cast<int>(merged.size());
      merged.push_back(groups[r]);
    } else if (r != static_cast<int>(g)) {
      auto& t = merged[group_index[r]].traces;
      t.insert(t.end(), groups[g].traces.begin(), groups[g].traces.end());
    }
  }
  for (size_t g = 0; g < groups.size(); ++g) group_index[g] = group_index[group_uf.find(g)];
  for (auto& pg : merged) std::sort(pg.traces.begin(), pg.traces.end());
  for (auto& s : segments) s.group = group_index[s.group];
  return merged;
}

}  // namespace rockface::faces::network_phases
