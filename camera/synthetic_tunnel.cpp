#include "camera/synthetic_tunnel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/error.h"

namespace rockface::camera {

namespace {

// sin^2 over [a, b], zero outside: smooth (C1) edges that stereo matching
// follows without the steps a box would leave.
double bump(double x, double a, double b) {
  if (!(x > a && x < b)) return 0;
  const double t = std::sin(std::numbers::pi * (x - a) / (b - a));
  return t * t;
}

// Signed curvature of the outline at s: 1/R toward an arc's centre on a
// counter-clockwise arc (convex), negative on a clockwise (concave) one.
double curvature_at(const tunnel::DesignProfile& profile, double s) {
  double start = 0;
  for (const auto& seg : profile.segments()) {
    const double len = seg.length();
    if (s < start + len || &seg == &profile.segments().back()) {
      if (seg.kind == tunnel::ProfileSegment::Kind::line) return 0;
      return (seg.sweep() > 0 ? 1.0 : -1.0) / seg.radius();
    }
    start += len;
  }
  return 0;
}

}  // namespace

double rendered_deviation(const RenderedTunnelSpec& spec, double chainage, double s) {
  double d = 0;
  for (const auto& b : spec.breaks)
    d += b.depth_m * bump(chainage, b.chainage_from, b.chainage_to) * bump(s, b.s_from, b.s_to);
  return d;
}

SectionTruth rendered_section_truth(const RenderedTunnelSpec& spec,
                                    const tunnel::DesignProfile& profile, double chainage,
                                    double s_from, double s_to) {
  if (s_to < 0) s_to = profile.perimeter();
  SectionTruth truth;
  const double ds = 1e-3;
  for (double s = s_from + ds / 2; s < s_to; s += ds) {
    const double d = rendered_deviation(spec, chainage, s);
    if (d == 0) continue;
    const double a = d * (1 + curvature_at(profile, s) * d / 2) * ds;
    if (a > 0)
      truth.overbreak_m2 += a;
    else
      truth.underbreak_m2 -= a;
  }
  return truth;
}

std::vector<SyntheticPatch> rendered_tunnel_patches(const RenderedTunnelSpec& spec,
                                                    const tunnel::Alignment& alignment,
                                                    const tunnel::DesignProfile& profile,
                                                    const std::string& where) {
  if (!(spec.face_chainage != spec.chainage_from))
    throw InputError(where, "the rendered tunnel has no length (face_chainage = from_chainage)");
  if (!(spec.section_m > 0) || !(spec.facet_m > 0))
    throw InputError(where, "section_m and facet_m must be positive");
  for (double c : {spec.chainage_from, spec.face_chainage})
    if (!alignment.contains(c))
      throw InputError(where, "chainage " + std::to_string(c) + " is off the alignment (" +
                                  std::to_string(alignment.first_chainage()) + " to " +
                                  std::to_string(alignment.last_chainage()) + ")");
  // Arc lengths: every segment's ends (the corners stay sharp) and a facet
  // every facet_m in between.
  std::vector<double> s_values;
  double start = 0;
  for (const auto& seg : profile.segments()) {
    const double len = seg.length();
    const int n = std::max(1, static_cast<int>(std::ceil(len / spec.facet_m)));
    for (int k = 0; k < n; ++k) s_values.push_back(start + len * k / n);
    start += len;
  }
  const int cols = static_cast<int>(s_values.size());

  // The face bulges toward the cameras as a shallow four-sided pyramid
  // (apex on the ray centre): each quarter is planar, so a joint's trace
  // bends where it crosses from one to the next, as it does on a real face,
  // and its plane can be measured from the trace alone.
  const double toward = spec.face_chainage > spec.chainage_from ? -1.0 : 1.0;
  const tunnel::TunnelFrame face_frame = alignment.frame_at(spec.face_chainage);
  const Eigen::Vector2d apex = profile.ray_centre();
  double reach_u = 1e-9, reach_v = 1e-9;
  for (double s : s_values) {
    const Eigen::Vector2d p = profile.point_at_length(s) - apex;
    reach_u = std::max(reach_u, std::abs(p.x()));
    reach_v = std::max(reach_v, std::abs(p.y()));
  }
  auto relief = [&](const Eigen::Vector2d& q) {
    const Eigen::Vector2d p = q - apex;
    return spec.face_relief_m * (1 - (std::abs(p.x()) / reach_u + std::abs(p.y()) / reach_v) / 2);
  };
  auto face_point = [&](const Eigen::Vector2d& q) -> Eigen::Vector3d {
    return face_frame.to_local(q.x(), q.y()) + toward * relief(q) * face_frame.along;
  };
  auto section_uv = [&](double chainage, double s) -> Eigen::Vector2d {
    return profile.point_at_length(s) +
           rendered_deviation(spec, chainage, s) * profile.outward_normal_at_length(s);
  };
  // The walls run in rows to half a section short of the face's deepest
  // outline point; the last row is the face's outline (which the relief
  // pulls up to face_relief_m toward the cameras).
  const double wall_end = spec.face_chainage + toward * (spec.face_relief_m + 0.5 * spec.section_m);
  const double length = std::abs(wall_end - spec.chainage_from);
  const int rows = 1 + std::max(1, static_cast<int>(std::ceil(length / spec.section_m)));
  std::vector<std::vector<Eigen::Vector3d>> grid(rows + 1);
  for (int i = 0; i <= rows; ++i) {
    const double chainage =
        i == rows ? spec.face_chainage
                  : spec.chainage_from + (wall_end - spec.chainage_from) * i / (rows - 1);
    for (double s : s_values) {
      const Eigen::Vector2d q = section_uv(chainage, s);
      // The walls' last row is the face's outline, where the face meets them.
      grid[i].push_back(i == rows
                            ? face_point(q)
                            : Eigen::Vector3d(alignment.frame_at(chainage).to_local(q.x(), q.y())));
    }
  }
  std::vector<SyntheticPatch> patches;
  patches.reserve(static_cast<std::size_t>(rows) * cols * 2 + 4);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int jn = (j + 1) % cols;
      const std::string id = "TUNNEL-" + std::to_string(i) + "-" + std::to_string(j) + "-";
      patches.push_back({id + "0", {grid[i][j], grid[i + 1][j], grid[i + 1][jn]}});
      patches.push_back({id + "1", {grid[i][j], grid[i + 1][jn], grid[i][jn]}});
    }
  // The face's quarters: the outline split where it crosses the lines
  // through the apex (u = apex u, v = apex v), each run closed at the apex.
  std::vector<Eigen::Vector2d> outline;
  for (double s : s_values) outline.push_back(section_uv(spec.face_chainage, s));
  auto quarter = [&](const Eigen::Vector2d& q) {
    return (q.x() >= apex.x() ? 1 : 0) + (q.y() >= apex.y() ? 2 : 0);
  };
  std::vector<std::pair<int, std::vector<Eigen::Vector2d>>> runs;
  for (int j = 0; j < cols; ++j) {
    const Eigen::Vector2d a = outline[j], b = outline[(j + 1) % cols];
    if (runs.empty() || runs.back().first != quarter(a)) runs.push_back({quarter(a), {}});
    // An outline vertex on a line through the apex is also the crossing
    // that closed the previous run: keep it once.
    if (runs.back().second.empty() || (runs.back().second.back() - a).norm() > 1e-12)
      runs.back().second.push_back(a);
    // Crossings of the two lines between a and b, in order along a -> b.
    std::vector<double> ts;
    for (int axis = 0; axis < 2; ++axis) {
      const double da = a[axis] - apex[axis], db = b[axis] - apex[axis];
      if ((da >= 0) != (db >= 0)) ts.push_back(da / (da - db));
    }
    std::sort(ts.begin(), ts.end());
    for (double t : ts) {
      const Eigen::Vector2d x = a + t * (b - a);
      // (When the crossing is `a` itself it already ends this run.)
      if ((x - runs.back().second.back()).norm() > 1e-12) runs.back().second.push_back(x);
      runs.push_back({quarter(b), {x}});
    }
  }
  // The last run continues the first (the outline is closed).
  if (runs.size() > 1 && runs.back().first == runs.front().first) {
    auto& last = runs.back().second;
    for (const auto& x : runs.front().second)
      if (last.empty() || (x - last.back()).norm() > 1e-12) last.push_back(x);
    runs.erase(runs.begin());
  }
  int n = 0;
  for (const auto& [q, run] : runs) {
    // A run of one point (the outline touching a line through the apex at
    // a vertex) encloses nothing.
    Eigen::Vector2d twice_area = Eigen::Vector2d::Zero();
    for (std::size_t k = 0; k + 1 < run.size(); ++k) {
      const Eigen::Vector2d a = run[k] - apex, b = run[k + 1] - apex;
      twice_area.x() += a.x() * b.y() - a.y() * b.x();
    }
    if (std::abs(twice_area.x()) < 1e-6) continue;
    // Points in line with their neighbours (the facets of a straight
    // invert) add nothing to the polygon and give the free surface's convex
    // partition zero-angle corners: dropped.
    std::vector<Eigen::Vector2d> corners{apex};
    for (std::size_t k = 0; k < run.size(); ++k) {
      const Eigen::Vector2d& prev = corners.back();
      const Eigen::Vector2d& next = k + 1 < run.size() ? run[k + 1] : apex;
      const Eigen::Vector2d d1 = run[k] - prev, d2 = next - run[k];
      if (std::abs(d1.x() * d2.y() - d1.y() * d2.x()) > 1e-9 * d1.norm() * d2.norm() ||
          d1.dot(d2) < 0)
        corners.push_back(run[k]);
    }
    SyntheticPatch face{"FACE-" + std::to_string(++n), {}};
    for (const auto& x : corners) face.polygon.push_back(face_point(x));
    patches.push_back(std::move(face));
  }
  return patches;
}

}  // namespace rockface::camera
