#include "firmware-app/tunnel/rendered_tunnel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/error.h"

namespace rockface::app {

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

RenderedTunnelSpec rendered_tunnel_spec(const storage::SceneTunnelRender& render) {
  RenderedTunnelSpec spec;
  spec.chainage_from = render.from_chainage;
  spec.face_chainage = render.face_chainage;
  spec.section_m = render.section_m;
  spec.facet_m = render.facet_m;
  for (const auto& b : render.breaks)
    spec.breaks.push_back({b.chainage_from, b.chainage_to, b.s_from, b.s_to, b.depth_m});
  return spec;
}

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

std::vector<camera::SyntheticPatch> rendered_tunnel_patches(const RenderedTunnelSpec& spec,
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
  const double length = std::abs(spec.face_chainage - spec.chainage_from);
  const int rows = std::max(1, static_cast<int>(std::ceil(length / spec.section_m)));
  auto point = [&](double chainage, double s) {
    const Eigen::Vector2d p = profile.point_at_length(s);
    const Eigen::Vector2d n = profile.outward_normal_at_length(s);
    const Eigen::Vector2d q = p + rendered_deviation(spec, chainage, s) * n;
    return alignment.frame_at(chainage).to_local(q.x(), q.y());
  };
  std::vector<std::vector<Eigen::Vector3d>> grid(rows + 1);
  std::vector<double> chainages(rows + 1);
  for (int i = 0; i <= rows; ++i) {
    chainages[i] = spec.chainage_from + (spec.face_chainage - spec.chainage_from) * i / rows;
    for (double s : s_values) grid[i].push_back(point(chainages[i], s));
  }
  std::vector<camera::SyntheticPatch> patches;
  patches.reserve(static_cast<std::size_t>(rows) * cols * 2 + 1);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int jn = (j + 1) % cols;
      const std::string id = "TUNNEL-" + std::to_string(i) + "-" + std::to_string(j) + "-";
      patches.push_back({id + "0", {grid[i][j], grid[i + 1][j], grid[i + 1][jn]}});
      patches.push_back({id + "1", {grid[i][j], grid[i + 1][jn], grid[i][jn]}});
    }
  patches.push_back({"FACE", grid[rows]});
  return patches;
}

}  // namespace rockface::app
