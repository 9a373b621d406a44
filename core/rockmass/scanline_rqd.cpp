#include "core/rockmass/scanline_rqd.h"

#include <algorithm>
#include <cmath>

#include "core/rockmass/tolerances.h"

namespace rockface::rockmass {

double priest_hudson_rqd(double lambda) {
  return 100.0 * std::exp(-kRqdPieceM * lambda) * (kRqdPieceM * lambda + 1.0);
}

namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The part [t0, t1] of the line a + t d inside the convex outline (ccw).
bool clip(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& a,
          const Eigen::Vector2d& d, double& t0, double& t1) {
  t0 = -1e300;
  t1 = 1e300;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& p = poly[i];
    const Eigen::Vector2d e = poly[(i + 1) % poly.size()] - p;
    // Inside: cross(e, x - p) >= 0.
    const double num = cross2(e, a - p), den = cross2(e, d);
    if (den == 0) {
      if (num < 0) return false;
      continue;
    }
    const double t = -num / den;
    if (den > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return t1 > t0;
}

// Parameters t in [t0, t1] where the line crosses the polyline.
void crossings(const std::vector<Eigen::Vector2d>& line, const Eigen::Vector2d& a,
               const Eigen::Vector2d& d, double t0, double t1, std::vector<double>& out) {
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const Eigen::Vector2d q = line[i], e = line[i + 1] - line[i];
    const double den = cross2(d, e);
    if (den == 0) continue;  // parallel: touching along is no crossing
    const Eigen::Vector2d w = q - a;
    const double t = cross2(w, e) / den;
    const double s = cross2(w, d) / den;
    // Half-open in s so that a line through a shared vertex counts once.
    if (s >= 0 && s < 1 && t >= t0 && t <= t1) out.push_back(t);
  }
}

}  // namespace

ScanlineRqd scanline_rqd(const std::vector<FaceTrace>& traces, const SetTraces& assigned,
                         const std::vector<SetInput>& sets, const std::vector<SetSpacing>& spacings,
                         const FaceWindow& window) {
  std::vector<std::vector<Eigen::Vector2d>> flat(traces.size());
  for (std::size_t i = 0; i < traces.size(); ++i)
    for (const auto& p : traces[i].points) flat[i].push_back(window.to_face(p));
  const double blind_cos = std::cos(kBlindZoneDeg * M_PI / 180.0);

  ScanlineRqd out;
  const struct {
    const char* name;
    double angle;
  } kinds[] = {{"horizontal", 0}, {"vertical", 90}, {"inclined 45 deg", 45}};
  double rqd_sum = 0, ph_sum = 0;
  int rqd_n = 0, ph_n = 0;
  for (const auto& kind : kinds) {
    ScanlineDirection dir;
    dir.name = kind.name;
    dir.angle_deg = kind.angle;
    dir.direction = window.direction(kind.angle);
    const double a = kind.angle * M_PI / 180.0;
    const Eigen::Vector2d d(std::cos(a), std::sin(a)), across(-d.y(), d.x());
    double lo = 1e300, hi = -1e300;
    for (const auto& p : window.outline) {
      lo = std::min(lo, p.dot(across));
      hi = std::max(hi, p.dot(across));
    }
    std::vector<int> set_crossings(sets.size(), 0);
    double intact = 0;
    for (int k = 0; k < kScanlinesPerDirection; ++k) {
      const double offset = lo + (hi - lo) * (k + 0.5) / kScanlinesPerDirection;
      const Eigen::Vector2d origin = offset * across;
      double t0 = 0, t1 = 0;
      if (!clip(window.outline, origin, d, t0, t1)) continue;
      std::vector<double> cut;
      for (std::size_t i = 0; i < flat.size(); ++i) {
        const std::size_t before = cut.size();
        crossings(flat[i], origin, d, t0, t1, cut);
        const int set = assigned.set_of[i];
        if (set >= 0) set_crossings[set] += static_cast<int>(cut.size() - before);
      }
      std::sort(cut.begin(), cut.end());
      double from = t0;
      cut.push_back(t1);
      for (double t : cut) {
        if (t - from >= kRqdPieceM) intact += t - from;
        from = t;
      }
      ++dir.lines;
      dir.length_m += t1 - t0;
      dir.crossings += static_cast<int>(cut.size()) - 1;
    }
    if (dir.length_m > 0) {
      dir.frequency_per_m = dir.crossings / dir.length_m;
      dir.rqd_percent = 100.0 * intact / dir.length_m;
      dir.priest_hudson_from_frequency = priest_hudson_rqd(dir.frequency_per_m);
      rqd_sum += *dir.rqd_percent;
      ++rqd_n;
      out.lowest_percent =
          out.lowest_percent ? std::min(*out.lowest_percent, *dir.rqd_percent) : *dir.rqd_percent;
    }
    double lambda = 0;
    bool any = false;
    for (std::size_t k = 0; k < sets.size(); ++k) {
      SetOnLine s;
      s.label = sets[k].label;
      s.crossings = set_crossings[k];
      s.cos_delta = std::abs(sets[k].normal.normalized().dot(dir.direction));
      s.in_blind_zone = s.cos_delta < blind_cos;
      if (s.crossings > 0 && dir.length_m > 0) {
        s.apparent_m = dir.length_m / s.crossings;
        if (!s.in_blind_zone) s.corrected_m = *s.apparent_m * s.cos_delta;
      }
      if (k < spacings.size() && spacings[k].mean_m) {
        lambda += s.cos_delta / *spacings[k].mean_m;
        any = true;
      }
      dir.sets.push_back(s);
    }
    if (any) {
      dir.frequency_from_sets_per_m = lambda;
      dir.priest_hudson_from_spacing = priest_hudson_rqd(lambda);
      ph_sum += *dir.priest_hudson_from_spacing;
      ++ph_n;
    }
    out.directions.push_back(std::move(dir));
  }
  if (rqd_n > 0) out.rqd_percent = rqd_sum / rqd_n;
  if (ph_n > 0) out.priest_hudson_from_spacing = ph_sum / ph_n;
  return out;
}

}  // namespace rockface::rockmass
